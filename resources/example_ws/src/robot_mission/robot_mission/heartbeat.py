"""A minimal liveness signal, written in the procedural style."""

import rclpy
from std_msgs.msg import Empty


def main(args=None):
    rclpy.init(args=args)
    node = rclpy.create_node('heartbeat')
    publisher = node.create_publisher(Empty, 'heartbeat', 1)
    node.create_timer(0.5, lambda: publisher.publish(Empty()))
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()
