import rclpy
from rclpy.node import Node

from geometry_msgs.msg import PoseStamped, TwistStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan


class Follower(Node):
    """Drives the simulated robot from its scans and odometry towards a goal."""

    def __init__(self):
        super().__init__('follower')
        self.scan_sub = self.create_subscription(LaserScan, 'scan', self.on_scan, 10)
        self.odom_sub = self.create_subscription(Odometry, 'odom', self.on_odom, 10)
        self.goal_sub = self.create_subscription(PoseStamped, 'goal_pose', self.on_goal, 1)
        self.cmd_pub = self.create_publisher(TwistStamped, 'cmd_vel', 10)

    def on_scan(self, msg):
        pass

    def on_odom(self, msg):
        pass

    def on_goal(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Follower())
