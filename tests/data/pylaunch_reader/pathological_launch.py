from launch import LaunchDescription
from launch_ros.actions import Node


def forever(n):
    return forever(n + 1)


def generate_launch_description():
    while True:
        pass
    nodes = [Node(package='p', executable='e')]
    text = 'x'
    for i in range(30):
        nodes = [nodes, nodes]
        text = text + text
    return LaunchDescription([forever(0), Node(package='p', executable=text), nodes])
