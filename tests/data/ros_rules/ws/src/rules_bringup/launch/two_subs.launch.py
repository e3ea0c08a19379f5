# Rule: delegation is one to one.
#
# Two listeners of the same topic and no publisher of it in this file.
# Expected:
#   listener_a and listener_b both subscribe /scan;
#   no topic inside the file (two subscribers are not each other's counterpart);
#   TWO boundary ports, both of type sensor_msgs/msg/LaserScan and both noted scan,
#   one delegation to each listener (not one shared boundary port).
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='rules_nodes', executable='scan_listener', name='listener_a'),
        Node(package='rules_nodes', executable='scan_listener', name='listener_b'),
    ])
