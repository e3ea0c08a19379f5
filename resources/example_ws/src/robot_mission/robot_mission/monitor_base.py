"""Common base for the robot's monitoring nodes."""

from diagnostic_msgs.msg import DiagnosticArray
from rclpy.node import Node


class MonitorBase(Node):
    """Publishes the monitor's findings on the shared diagnostics topic."""

    def __init__(self, node_name):
        super().__init__(node_name)
        self.diagnostics_pub = self.create_publisher(DiagnosticArray, '/diagnostics', 10)

    def report(self, status):
        msg = DiagnosticArray()
        msg.status.append(status)
        self.diagnostics_pub.publish(msg)
