import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    guard_params = os.path.join(
        get_package_share_directory('rover_bringup'), 'config', 'guard.yaml')
    return LaunchDescription([
        Node(package='rover_motion', executable='smoother', name='smoother'),
        Node(package='rover_motion', executable='speed_guard', name='speed_guard',
             parameters=[guard_params]),
    ])
