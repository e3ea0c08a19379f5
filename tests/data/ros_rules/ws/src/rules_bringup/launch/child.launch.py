# Included twice by twice.launch.py. It sets no namespace itself and starts only a
# listener of the relative topic `scan`; nothing here publishes `scan`.
# Expected, analysed on its own:
#   listener  subscribes scan (relative: /scan at the root)  -> promoted, one boundary port.
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='rules_nodes', executable='scan_listener', name='listener'),
    ])
