"""Starts every node of the demo robot, all in the root namespace."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_robot', executable='vision_camera', name='vision_camera'),
        Node(package='demo_robot', executable='vision_detector', name='vision_detector'),
        Node(package='demo_robot', executable='vision_tracker', name='vision_tracker'),
        Node(package='demo_robot', executable='decision_planner', name='decision_planner'),
        Node(package='demo_robot', executable='decision_controller', name='decision_controller'),
        Node(package='demo_robot', executable='tf_broadcaster', name='tf_broadcaster'),
        Node(package='demo_robot', executable='status_reporter', name='status_reporter'),
    ])
