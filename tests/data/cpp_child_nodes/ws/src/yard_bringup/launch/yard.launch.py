import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    params = os.path.join(get_package_share_directory('yard_bringup'), 'config', 'yard_params.yaml')
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('rover'),
            Node(package='yard_servers', executable='path_server', parameters=[params]),
            Node(package='yard_servers', executable='drive_server', parameters=[params]),
            Node(package='yard_servers', executable='grid_watcher'),
        ]),
    ])
