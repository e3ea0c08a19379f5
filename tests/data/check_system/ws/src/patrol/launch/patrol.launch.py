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
    ])
