from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='yard_watch', executable='worker', name='lift'),
        Node(package='yard_watch', executable='worker', name='belt'),
        Node(package='yard_watch', executable='watchdog', name='watchdog',
             parameters=[{'watched_nodes': ['lift', 'belt'], 'zones': ['dock', 'ramp']}]),
        Node(package='yard_watch', executable='sensor_hub', name='sensor_hub',
             parameters=[{'feeds': ['front', 'rear', 'bumper'], 'rear.topic': 'rear_scan',
                          'bumper.kind': 'sonar'}]),
    ])
