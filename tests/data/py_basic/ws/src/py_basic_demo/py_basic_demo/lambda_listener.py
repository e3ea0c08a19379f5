import rclpy
from rclpy import node as rclpy_node
import std_msgs.msg


class LambdaListener(rclpy_node.Node):

    def __init__(self):
        super().__init__(node_name='lambda_listener')
        self.create_subscription(
            msg_type=std_msgs.msg.String,
            topic='chatter',
            callback=lambda msg: self.get_logger().info(msg.data),
            qos_profile=10)


def main():
    rclpy.init()
    rclpy.spin(LambdaListener())
