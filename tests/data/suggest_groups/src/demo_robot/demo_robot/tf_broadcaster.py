"""Broadcasts the static transforms of the robot body."""

import rclpy
from rclpy.node import Node
from tf2_msgs.msg import TFMessage


class TfBroadcaster(Node):

    def __init__(self):
        super().__init__('tf_broadcaster')
        self.tf_pub = self.create_publisher(TFMessage, '/tf', 10)


def main():
    rclpy.init()
    rclpy.spin(TfBroadcaster())
