from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # No lists given: the watchdog's per-item names are only known at run time. In its own
    # namespace, its summary is /yard/watch_summary and its state /yard/watchdog/state.
    return LaunchDescription([
        Node(package='yard_watch', executable='watchdog', name='watchdog', namespace='yard'),
    ])
