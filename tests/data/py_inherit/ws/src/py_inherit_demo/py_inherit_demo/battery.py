import rclpy
from sensor_msgs.msg import BatteryState

from .base import EstopMixin, MonitorBase


class BatteryMonitor(EstopMixin, MonitorBase):

    def __init__(self):
        super().__init__('battery_monitor')
        self.create_subscription(BatteryState, 'battery', self.on_battery, 10)
        self.add_estop()

    def setup(self):
        # replaces the base's heartbeat: no super().setup()
        self.create_publisher(BatteryState, 'battery_summary', 1)

    def on_battery(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(BatteryMonitor())
