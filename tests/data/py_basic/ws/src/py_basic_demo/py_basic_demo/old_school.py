import rclpy
from std_msgs.msg import String


def on_message(msg):
    print(msg.data)


def main(args=None):
    rclpy.init(args=args)
    node = rclpy.create_node('old_school')
    publisher = node.create_publisher(String, 'chatter', 10)
    node.create_subscription(String, 'echo', on_message, 10)
    publisher.publish(String(data='hi'))
    rclpy.spin(node)
