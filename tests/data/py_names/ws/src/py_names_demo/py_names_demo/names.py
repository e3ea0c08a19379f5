import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from sensor_msgs.msg import Image
from std_msgs.msg import String

STATUS_TOPIC = 'status'


class Names(Node):
    """Every way a topic name reaches a create call."""

    CLASS_TOPIC = 'class_topic'

    def __init__(self):
        super().__init__('names')
        self.topic = 'member_topic'
        local_topic = 'local_topic'
        self.declare_parameter('input_topic', 'camera/image')
        self.declare_parameter('output_topic', 'out')
        self.declare_parameter('use_debug', False)
        self.declare_parameter('rate', 10)
        self.declare_parameters(namespace='', parameters=[('cmd_topic', 'cmd_vel'), ('frame', 'base')])
        self.create_publisher(String, self.topic, 10)
        self.create_publisher(String, local_topic, 10)
        self.create_subscription(Image, self.get_parameter('input_topic').value, self.on_image, 10)
        out = self.get_parameter('output_topic').get_parameter_value().string_value
        self.create_publisher(Image, out, 10)
        self.create_publisher(String, '~/private', 10)
        self.create_publisher(String, STATUS_TOPIC, 10)
        self.create_publisher(String, self.get_name() + '/debug', 10)
        self.create_publisher(String, f'{self.get_name()}/formatted', 10)
        self.create_publisher(String, self.CLASS_TOPIC, 10)
        self.create_publisher(Twist, self.get_parameter('cmd_topic').value, 10)
        self.mirror = self.declare_parameter('mirror_topic', 'mirror').value
        self.create_publisher(Image, self.mirror, 10)
        self.debug = self.get_parameter('use_debug').value
        if self.debug:
            self.create_publisher(Image, 'debug_image', 1)
        if self.get_parameter('rate').value > 5:
            self.create_publisher(String, 'fast', 10)
        else:
            self.create_publisher(String, 'slow', 10)

    def on_image(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Names())
