import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String


class Pass(Node):

    def __init__(self, name, source, target):
        super().__init__(name)
        self.pub = self.create_publisher(String, target, 10)
        self.create_subscription(String, source, self.pub.publish, 10)


def make_line():
    return [Pass('first', 'raw', 'middle'), Pass('second', 'middle', 'done')]


def main():
    rclpy.init()
    executor = SingleThreadedExecutor()
    for node in make_line():
        executor.add_node(node)
    executor.spin()
