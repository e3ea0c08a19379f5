import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Before(Node):

    def __init__(self):
        super().__init__('before')
        self.create_publisher(String, 'before_topic', 10)


def half_written(:
    return [1, 2


class After(Node):

    def __init__(self):
        super().__init__('after')
        self.create_subscription(String, 'after_topic', self.on_msg, 10)

    def on_msg(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(After())
