"""Owns the robot's operating mode."""

import rclpy
from rclpy.node import Node
from robot_interfaces.srv import SetMode
from std_msgs.msg import String as StringMsg


class ModeManager(Node):
    """Accepts mode changes and announces the current mode."""

    def __init__(self):
        super().__init__('mode_manager')
        self.mode = 'idle'
        self.mode_pub = self.create_publisher(StringMsg, '~/mode', 1)
        self.mode_srv = self.create_service(SetMode, 'set_mode', self.handle_set_mode)

    def handle_set_mode(self, request, response):
        response.previous_mode = self.mode
        self.mode = request.mode
        response.accepted = True
        self.mode_pub.publish(StringMsg(data=self.mode))
        return response


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(ModeManager())
    rclpy.shutdown()
