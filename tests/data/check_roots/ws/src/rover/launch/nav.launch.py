from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # The planner as the navigation stack starts it: on the map the SLAM node builds.
    return LaunchDescription([
        Node(package='rover', executable='planner', name='planner',
             remappings=[('map', '/slam/map')]),
    ])
