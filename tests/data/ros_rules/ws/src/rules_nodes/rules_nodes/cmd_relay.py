import rclpy
from rclpy.node import Node

from geometry_msgs.msg import Twist


class CmdRelay(Node):
    """Forwards velocity commands; its input name is relative and has two segments."""

    def __init__(self):
        super().__init__('cmd_relay')
        self.create_subscription(Twist, 'robo/cmd_vel', self.on_cmd, 10)
        self.out_pub = self.create_publisher(Twist, 'cmd_out', 10)

    def on_cmd(self, msg):
        self.out_pub.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(CmdRelay())
