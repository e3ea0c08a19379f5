import rclpy
from rclpy.executors import MultiThreadedExecutor

from py_basic_demo.listener import Listener
from . import talker


def run():
    rclpy.init()
    executor = MultiThreadedExecutor()
    executor.add_node(talker.Talker())
    executor.add_node(Listener())
    executor.spin()
