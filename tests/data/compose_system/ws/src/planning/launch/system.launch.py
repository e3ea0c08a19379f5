from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace, SetRemap
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    vision = PathJoinSubstitution([FindPackageShare('vision'), 'launch', 'vision.launch.xml'])
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='false'),
        GroupAction([
            PushRosNamespace('front'),
            IncludeLaunchDescription(AnyLaunchDescriptionSource(vision),
                                     launch_arguments={'camera_name': 'front'}.items()),
        ]),
        GroupAction([
            PushRosNamespace('rear'),
            SetRemap(src='/detections', dst='/rear/detections'),
            IncludeLaunchDescription(AnyLaunchDescriptionSource(vision),
                                     launch_arguments={'camera_name': 'rear', 'exposure': 'false'}.items()),
        ]),
        Node(package='planning', executable='planner', name='planner',
             remappings=[('cmd_vel', '/robot/cmd_vel')]),
        Node(package='planning', executable='planner', name='backup_planner',
             remappings=[('cmd_vel', '/robot/cmd_vel')]),
        Node(package='planning', executable='commander', name='commander'),
        Node(package='planning', executable='commander', name='sim_commander',
             condition=IfCondition(LaunchConfiguration('use_sim'))),
    ])
