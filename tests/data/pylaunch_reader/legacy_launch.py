from launch import LaunchDescription
from launch_ros.actions import LifecycleNode, Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='old', node_executable='talker', node_name='old_talker', node_namespace='legacy'),
        LifecycleNode(package='lc', executable='lc_talker', name='lc_talker', namespace=''),
        LifecycleNode(package='lc', executable='lc_listener', node_name='lc_listener', namespace='ns'),
    ])
