import rclpy
from rclpy.node import Node


class Stage(Node):
    """One relay stage."""

    def __init__(self, name):
        super().__init__(name)


def level_four():
    return Stage('deep_stage')


def level_three():
    return [level_four(), Stage('third_stage')]


def level_two():
    return level_three()


def level_one():
    return level_two()


def main():
    rclpy.init()
    nodes = [Stage('first_stage')] + level_one()
    rclpy.spin(nodes[0])
