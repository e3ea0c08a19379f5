import rclpy
from rclpy.node import Node

from nav_msgs.msg import Odometry
from std_msgs.msg import Bool
from std_srvs.srv import Trigger


class SafetyMonitor(Node):

    def __init__(self):
        super().__init__('safety_monitor')
        self.create_subscription(Odometry, 'odom', self.on_odom, 10)
        self.estop_pub = self.create_publisher(Bool, '/estop', 10)
        self.create_service(Trigger, 'reset_estop', self.on_reset)

    def on_odom(self, msg):
        pass

    def on_reset(self, request, response):
        return response


def main():
    rclpy.init()
    rclpy.spin(SafetyMonitor())
