from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value='chat'),
        DeclareLaunchArgument('quiet', default_value='false'),
        GroupAction([
            PushRosNamespace(LaunchConfiguration('ns')),
            Node(package='chat_demo', executable='talker', name='talker',
                 remappings=[('chatter', 'conversation')]),
            Node(package='chat_demo', executable='listener', name='listener',
                 parameters=[{'rate': '5'}],
                 remappings=[('chatter', 'conversation')],
                 condition=UnlessCondition(LaunchConfiguration('quiet'))),
        ]),
    ])
