import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(
        get_package_share_directory('drive_bringup'), 'config', 'drive_params.yaml')
    return LaunchDescription([
        Node(package='drive_servers', executable='speed_limiter',
             name='speed_limiter', parameters=[params]),
        Node(package='drive_servers', executable='follow_server',
             name='follow_server', parameters=[params, {'controller_frequency': 15.0}]),
        Node(package='drive_py', executable='battery_watch',
             name='battery_watch', parameters=[params]),
        Node(package='drive_py', executable='relay_any',
             name='relay_any', parameters=[params]),
    ])
