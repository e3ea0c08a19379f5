from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # No lists given: the watchdog's per-item names are only known at run time.
    return LaunchDescription([
        Node(package='yard_watch', executable='watchdog', name='watchdog'),
    ])
