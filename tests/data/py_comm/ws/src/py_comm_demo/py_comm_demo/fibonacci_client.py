from example_interfaces.action import Fibonacci as Fib
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node


class FibonacciClient(Node):

    def __init__(self):
        super().__init__('fibonacci_client')
        self._client = ActionClient(node=self, action_type=Fib, action_name='fibonacci')


def main():
    rclpy.init()
    rclpy.spin(FibonacciClient())
