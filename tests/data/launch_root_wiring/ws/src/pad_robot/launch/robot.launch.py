from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='pad_robot', executable='pad_server'),
        Node(package='pad_robot', executable='drive', remappings=[('joy', '/device/joy')]),
        Node(package='pad_robot', executable='arm', remappings=[('joy', '/device/joy')]),
        Node(package='pad_robot', executable='range_sim'),
        Node(package='pad_robot', executable='avoider'),
    ])
