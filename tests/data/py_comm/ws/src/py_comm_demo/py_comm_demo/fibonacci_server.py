from example_interfaces.action import Fibonacci
import rclpy
import rclpy.action
from rclpy.node import Node


class FibonacciServer(Node):

    def __init__(self):
        super().__init__('fibonacci_server')
        self._server = rclpy.action.ActionServer(
            self, Fibonacci, 'fibonacci',
            execute_callback=self.execute,
            goal_callback=self.accept)

    def accept(self, goal_request):
        return rclpy.action.GoalResponse.ACCEPT

    def execute(self, goal_handle):
        goal_handle.succeed()
        return Fibonacci.Result()


def main():
    rclpy.init()
    rclpy.spin(FibonacciServer())
