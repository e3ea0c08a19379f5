import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Image
from std_msgs.msg import String
from tf2_msgs.msg import TFMessage


# Finds objects in camera images.
# One detection message per frame.
class VisionDetector(Node):

    def __init__(self):
        super().__init__('vision_detector')
        self.image_sub = self.create_subscription(Image, 'image_raw', self.on_image, 10)
        self.detections_pub = self.create_publisher(String, 'detections', 10)
        self.tf_sub = self.create_subscription(TFMessage, '/tf', self.on_tf, 10)

    def on_image(self, msg):
        pass

    def on_tf(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(VisionDetector())
