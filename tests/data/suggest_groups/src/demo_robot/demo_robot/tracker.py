import rclpy
from diagnostic_msgs.msg import DiagnosticArray
from rclpy.node import Node
from std_msgs.msg import String


class VisionTracker(Node):
    """
    Tracks detected objects over time.

    Publishes one track list per detection message.
    """

    def __init__(self):
        super().__init__('vision_tracker')
        self.detections_sub = self.create_subscription(String, 'detections', self.on_detections, 10)
        self.tracks_pub = self.create_publisher(String, 'tracks', 10)
        self.diag_pub = self.create_publisher(DiagnosticArray, '/diagnostics', 10)

    def on_detections(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(VisionTracker())
