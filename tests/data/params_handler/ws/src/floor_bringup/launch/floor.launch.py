import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(get_package_share_directory('floor_bringup'), 'config', 'floor.yaml')
    return LaunchDescription([
        Node(package='floor_control', executable='floor_server', name='floor_server',
             parameters=[params]),
    ])
