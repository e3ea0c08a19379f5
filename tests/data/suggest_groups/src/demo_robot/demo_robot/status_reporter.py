import rclpy
from rclpy.node import Node
from std_msgs.msg import String


def topic_prefix():
    return 'robot'


class StatusReporter(Node):
    """Reports the overall status under a computed topic name."""

    def __init__(self):
        super().__init__('status_reporter')
        self.prefix = topic_prefix()
        self.status_pub = self.create_publisher(String, self.prefix + '/status', 10)


def main():
    rclpy.init()
    rclpy.spin(StatusReporter())
