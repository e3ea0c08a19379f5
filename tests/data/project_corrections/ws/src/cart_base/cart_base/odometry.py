import rclpy
from rclpy.node import Node

from nav_msgs.msg import Odometry
from std_msgs.msg import Int32MultiArray


class OdometryNode(Node):
    """Integrates wheel ticks into odometry."""

    def __init__(self, status_type):
        super().__init__('odometry')
        self.status_type = status_type
        self.create_subscription(Int32MultiArray, 'wheel_ticks', self.on_ticks, 10)
        self.odom_pub = self.create_publisher(Odometry, 'odom', 10)
        self.pose_pub = self.create_publisher(Odometry, self.frame_prefix() + '/pose', 10)
        self.status_pub = self.create_publisher(self.status_type, 'status', 10)

    def frame_prefix(self):
        return self.get_namespace()

    def on_ticks(self, msg):
        self.odom_pub.publish(Odometry())


def main():
    rclpy.init()
    rclpy.spin(OdometryNode(None))
