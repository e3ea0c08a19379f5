# Rule: an executable started under a package that does not build it.
#
# rules_bringup builds no executable; `teleop` is a console script of rules_nodes, the only
# package of the workspace that builds it. The instance is still typed by that class.
# Expected:
#   one part teleop: Teleop (no name given here, so the node name from the code, `teleop`);
#   it publishes /robo/cmd_vel (absolute in the code), promoted: one boundary port;
#   an info diagnostic that the executable is built by rules_nodes, not rules_bringup.
# A node of a package outside the workspace is a part typed `package/executable`, named by
# name= when given, else by its executable: here `joy_node: joy/joy_node`, with the ports of
# its interface model (interfaces/models/joy_node.json): it publishes joy and subscribes to
# joy/set_feedback, both promoted.
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='rules_bringup', executable='teleop'),
        Node(package='joy', executable='joy_node'),
    ])
