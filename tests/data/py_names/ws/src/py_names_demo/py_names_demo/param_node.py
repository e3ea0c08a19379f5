import rclpy
from std_msgs.msg import String


def main():
    rclpy.init()
    node = rclpy.create_node('param_node')
    node.declare_parameter('topic', 'from_param')
    topic = node.get_parameter('topic').value
    node.create_publisher(String, topic, 10)
    enabled = node.declare_parameter('enabled', True).value
    if enabled:
        node.create_subscription(String, 'feedback', lambda msg: None, 10)
    rclpy.spin(node)
