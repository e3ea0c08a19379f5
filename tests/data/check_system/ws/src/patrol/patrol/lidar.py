import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data

from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan


class Lidar(Node):
    """Publishes laser scans as sensor data, and wheel odometry."""

    def __init__(self):
        super().__init__('lidar')
        self.scan_pub = self.create_publisher(LaserScan, 'scan', qos_profile_sensor_data)
        self.odom_pub = self.create_publisher(Odometry, 'wheel_odom', 10)


def main():
    rclpy.init()
    rclpy.spin(Lidar())
