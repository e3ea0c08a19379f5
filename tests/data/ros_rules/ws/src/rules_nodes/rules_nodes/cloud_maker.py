import rclpy
from rclpy.node import Node

from sensor_msgs.msg import PointCloud2
from std_srvs.srv import Trigger


class CloudMaker(Node):
    """Publishes a cloud on a topic named by a parameter; serves stats only when enabled."""

    def __init__(self):
        super().__init__('cloud_maker')
        self.declare_parameter('output_topic', 'points')
        self.declare_parameter('enable_stats', False)
        # The topic name is the parameter's value: 'points' unless a launch file sets it.
        self.cloud_pub = self.create_publisher(
            PointCloud2, self.get_parameter('output_topic').value, 10)
        # A guarded port: the private service exists only when enable_stats is true.
        if self.get_parameter('enable_stats').value:
            self.create_service(Trigger, '~/stats', self.on_stats)

    def on_stats(self, request, response):
        response.success = True
        return response


def main():
    rclpy.init()
    rclpy.spin(CloudMaker())
