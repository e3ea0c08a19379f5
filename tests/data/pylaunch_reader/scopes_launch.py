from launch import LaunchDescription
from launch.actions import GroupAction, SetLaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace, PushROSNamespace, SetParameter, SetRemap


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('robot'),
            PushROSNamespace(namespace='arm'),
            SetRemap(src='/tf', dst='tf'),
            SetParameter(name='use_sim_time', value=True),
            Node(package='p', executable='e'),
        ]),
        GroupAction(actions=[SetLaunchConfiguration('mode', 'fast')], scoped=False),
        SetRemap('a', 'b'),
        GroupAction([Node(package='p', executable='f')], launch_configurations={'level': 'debug'}),
    ])
