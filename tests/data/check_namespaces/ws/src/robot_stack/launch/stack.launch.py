from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    robot = LaunchConfiguration('robot')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value=''),
        # The planner runs in the robot's namespace, pushed here.
        GroupAction([
            PushROSNamespace(robot),
            Node(package='planning_kit', executable='planner', name='planner'),
        ]),
        # The driver names its namespace itself.
        Node(package='drive_kit', executable='driver', name='driver', namespace=robot),
    ])
