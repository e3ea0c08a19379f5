import py_trees
import rclpy
from rclpy.node import Node

from bt_mission.reporter import StatusReporter
from bt_mission.tree import create_root


class Mission(Node):
    """Ticks the mission tree; its ports are made by the tree's behaviours and the reporter."""

    def __init__(self):
        super().__init__('mission')
        self.reporter = StatusReporter(node=self)
        self.tree = py_trees.trees.BehaviourTree(root=self.create_tree())
        self.tree.setup(node=self, timeout=15.0)
        self.create_timer(0.5, self.tick)

    def create_tree(self):
        return create_root('scout')

    def tick(self):
        self.tree.tick()
        self.reporter.report(str(self.tree.root.status))


def main():
    rclpy.init()
    rclpy.spin(Mission())
