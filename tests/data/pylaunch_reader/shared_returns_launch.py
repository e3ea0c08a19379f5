import sys

from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node


def setup(context):
    # The simulator runs in either case; the converter only when the vehicle model asks for it.
    simulator = Node(package='sim', executable='simulator', name='simulator')
    if 'no_converter' in sys.argv:
        return [simulator]
    converter = Node(package='sim', executable='converter', name='converter')
    return [simulator, converter]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
