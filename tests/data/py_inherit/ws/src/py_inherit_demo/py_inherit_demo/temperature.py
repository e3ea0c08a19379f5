import rclpy
from sensor_msgs.msg import Temperature

from py_inherit_demo import base


class TemperatureMonitor(base.MonitorBase):

    def setup(self):
        super().setup()
        self.create_subscription(Temperature, 'temperature', self.on_temperature, 10)

    def on_temperature(self, msg):
        pass


class CpuTemperatureMonitor(TemperatureMonitor):

    def __init__(self):
        super().__init__('cpu_temperature', status_topic='cpu_status')
        self.create_publisher(Temperature, 'cpu_temperature_max', 1)


def main():
    rclpy.init()
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(TemperatureMonitor('temperature_monitor'))
    executor.add_node(CpuTemperatureMonitor())
    executor.spin()
