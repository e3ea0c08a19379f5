import rclpy

from py_helper_demo import helpers


def main():
    rclpy.init()
    node = rclpy.create_node('scripted')
    relay = helpers.CommandRelay(node, topic='scripted_cmd')
    relay.start()
    rclpy.spin(node)
