import sys
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    if sys.argv[-1] == 'a':
        exe = 'first'
    elif sys.argv[-1] == 'b':
        exe = 'second'
    else:
        exe = 'third'
        only_else = 'x'
    node = Node(package='p', executable=exe, name=only_else)
    if len(sys.argv) > 2:
        return LaunchDescription([node])
    return LaunchDescription([Node(package='p', executable='fallback')])
