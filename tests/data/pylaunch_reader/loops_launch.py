from launch import LaunchDescription
from launch_ros.actions import Node

ROBOTS = [{'name': 'r1', 'x': 0.0}, {'name': 'r2', 'x': 1.5}]


def robot_node(robot, suffix=''):
    return Node(package='sim', executable='spawn', name=robot['name'] + suffix,
                parameters=[{'x': robot['x']}])


def topic(name):
    return '/' + name + '/cmd_vel'


def generate_launch_description():
    nodes = []
    for robot in ROBOTS:
        nodes.append(robot_node(robot, suffix='_spawner'))
    drivers = [Node(package='drv', executable='driver', namespace=n, remappings=[('cmd_vel', topic(n))]) for n in ['a', 'b'] if n != 'b']
    for i, name in enumerate(['x', 'y']):
        if i == 1:
            break
        nodes.append(Node(package='e', executable=name))
    for unknown in robots_from_yaml():
        nodes.append(Node(package='u', executable='per_robot', name=unknown))
    return LaunchDescription(nodes + drivers)
