"""Brings up one delivery robot under its own namespace."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import (
    AnyLaunchDescriptionSource, PythonLaunchDescriptionSource)
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import PushRosNamespace, SetRemap
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot_ns = LaunchConfiguration('robot_ns')
    use_camera = LaunchConfiguration('use_camera')
    launch_dir = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'launch'])

    robot = GroupAction([
        PushRosNamespace(robot_ns),
        SetRemap(src='/diagnostics', dst='/robot_diagnostics'),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(
                PathJoinSubstitution([launch_dir, 'sensing.launch.py'])),
            launch_arguments={'use_camera': use_camera}.items()),
        IncludeLaunchDescription(
            AnyLaunchDescriptionSource(
                PathJoinSubstitution([launch_dir, 'navigation.launch.xml'])),
            launch_arguments={'max_speed': '0.5'}.items()),
        IncludeLaunchDescription(
            AnyLaunchDescriptionSource(
                PathJoinSubstitution([launch_dir, 'mission.launch.yaml']))),
    ])

    return LaunchDescription([
        DeclareLaunchArgument('robot_ns', default_value='robot1',
                              description='Namespace of the robot'),
        DeclareLaunchArgument('use_camera', default_value='true',
                              description='Start the camera driver'),
        robot,
    ])
