"""Relays whatever it is configured with: it takes parameters nobody declares."""
import rclpy
from rclpy.node import Node


class RelayAny(Node):

    def __init__(self):
        super().__init__('relay_any', automatically_declare_parameters_from_overrides=True)
        self.declare_parameter('period', 1.0)


def main():
    rclpy.init()
    rclpy.spin(RelayAny())
