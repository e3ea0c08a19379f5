from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument as Arg
from launch_ros.actions import Node

COMMON = {'package': 'demo', 'output': 'screen'}

def generate_launch_description():
    declared = [Arg('x')]
    return LaunchDescription(declared + [Node(executable='e', **COMMON)])
