"""Classes named like nodes that are not ROS nodes."""
from anytree import Node


class TreeNode:

    def __init__(self, name):
        self.name = name
        self.children = []


class Leaf(Node):
    """A node of an anytree tree, not of a ROS graph."""

    def create_publisher(self, kind, name):
        return (kind, name)


class LocalNode:
    pass


class DerivedNode(LocalNode):
    pass
