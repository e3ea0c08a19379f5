from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot = LaunchConfiguration('robot')
    use_echo = LaunchConfiguration('use_echo')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='robot1',
                              description='Namespace of the robot'),
        DeclareLaunchArgument('use_echo', default_value='false',
                              description='Also start a talker that echoes'),
        Node(package='py_talker', executable='talker', name='talker',
             remappings=[('chatter', 'speech')],
             parameters=[{'rate': 2.0}]),
        GroupAction([
            PushRosNamespace(robot),
            IncludeLaunchDescription(
                AnyLaunchDescriptionSource(PathJoinSubstitution(
                    [FindPackageShare('cpp_listener'), 'launch', 'listener.launch.xml'])),
                launch_arguments={'topic': 'speech'}.items()),
        ]),
        Node(package='py_talker', executable='talker', name='echo_talker',
             condition=IfCondition(use_echo)),
    ])
