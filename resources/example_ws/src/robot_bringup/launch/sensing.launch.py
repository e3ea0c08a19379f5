"""The sensing pipeline: a component container with the lidar filter, and the camera."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    container = ComposableNodeContainer(
        name='sensing_container',
        namespace='',
        package='rclcpp_components',
        executable='component_container',
        composable_node_descriptions=[
            ComposableNode(
                package='robot_sensing',
                plugin='robot_sensing::LidarFilter',
                name='lidar_filter',
                remappings=[('scan', 'lidar/scan')],
                parameters=[{'output_topic': 'scan_filtered', 'max_range': 8.0}]),
        ])

    camera = Node(
        package='robot_sensing',
        executable='camera_driver',
        name='front_camera',
        parameters=[{'use_exposure_service': True}],
        condition=IfCondition(LaunchConfiguration('use_camera')))

    return LaunchDescription([
        DeclareLaunchArgument('use_camera', default_value='false'),
        container,
        camera,
    ])
