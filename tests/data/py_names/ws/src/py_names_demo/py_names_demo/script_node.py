import rclpy
from std_msgs.msg import String

if __name__ == '__main__':
    rclpy.init()
    node = rclpy.create_node('script_node')
    node.create_publisher(String, 'script_topic', 10)
    rclpy.spin(node)
