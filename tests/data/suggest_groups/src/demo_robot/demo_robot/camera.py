import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Image
from tf2_msgs.msg import TFMessage


class VisionCamera(Node):
    """Grabs frames from the front camera and publishes them."""

    def __init__(self):
        super().__init__('vision_camera')
        self.image_pub = self.create_publisher(Image, 'image_raw', 10)
        self.tf_pub = self.create_publisher(TFMessage, '/tf', 10)


def main():
    rclpy.init()
    rclpy.spin(VisionCamera())
