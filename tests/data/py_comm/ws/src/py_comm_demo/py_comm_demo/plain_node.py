import rclpy
from rclpy.node import Node
from std_srvs.srv import Trigger


def main():
    rclpy.init()
    node = Node('plain_node')
    reset = node.create_client(Trigger, 'reset')
    reset.call_async(Trigger.Request())
    rclpy.spin(node)
