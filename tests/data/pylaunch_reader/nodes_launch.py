from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    ns = LaunchConfiguration('ns', default='robot')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false', description='Use sim time'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker', namespace=ns,
             parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time'), 'rate': 10, 'gains': [1.0, 2.5], 'debug': True, 'pid': {'p': 0.5}}, '/etc/params.yaml'],
             remappings=[('chatter', '/chat'), ('/tf', 'tf')]),
        Node(package='demo_nodes_py', executable='listener', arguments=['--ros-args', '-r', 'chatter:=/chat']),
    ])
