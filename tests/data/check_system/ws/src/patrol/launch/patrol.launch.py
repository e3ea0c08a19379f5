from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='patrol', executable='lidar', name='lidar'),
        Node(package='patrol', executable='mapper', name='mapper',
             remappings=[('initialpose', '/initial_pose')]),
        Node(package='patrol', executable='viewer', name='viewer'),
        Node(package='patrol', executable='viewer', name='viewer'),
        Node(package='patrol', executable='teleop', name='teleop'),
        Node(package='drive', executable='base', name='base'),
        # Two helpers from outside the workspace, unnamed: their runtime names are not known
        # here, so they are not reported as a duplicate.
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['0', '0', '0', '0', '0', '0', 'base_link', 'laser']),
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['0', '0', '0', '0', '0', '0', 'base_link', 'imu']),
    ])
