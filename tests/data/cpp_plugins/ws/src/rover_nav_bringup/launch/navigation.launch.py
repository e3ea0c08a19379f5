import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(
        get_package_share_directory('rover_nav_bringup'), 'config', 'nav_params.yaml')
    return LaunchDescription([
        Node(package='rover_nav_servers', executable='navigator_server',
             name='navigator_server', parameters=[params]),
        Node(package='rover_nav_servers', executable='follow_server',
             name='follow_server', parameters=[params]),
    ])
