from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # One node: its open ports are its interface, not findings (odom goes to a driver); a rule
    # that renames no port of it still is one, and its misspelt 'mapp' leaves 'map' open where
    # mapping.launch.py remaps the same port.
    return LaunchDescription([
        Node(package='depot', executable='planner', name='planner',
             remappings=[('odom', '/wheel/odom'), ('mapp', '/map')]),
    ])
