from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    talker = Node(package='p', executable='talker')
    broken = = 1
    return LaunchDescription([talker, Node(package='p', executable='listener')])
