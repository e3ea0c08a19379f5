# Rule: remapping rules are matched on expanded names (relative name in code, absolute rule).
#
# cmd_relay subscribes `robo/cmd_vel`, relative in its code. In the root namespace that
# expands to /robo/cmd_vel, which is exactly the rule's left side, so the rule applies.
# teleop publishes `/robo/cmd_vel`, absolute in its code; the same rule applies to it trivially.
# Expected:
#   teleop     publishes  /mux/cmd_vel
#   cmd_relay  subscribes /mux/cmd_vel   (NOT /robo/cmd_vel: a rule compared as raw text would
#                                         miss `robo/cmd_vel` and leave the two parts unwired)
#   cmd_relay  publishes  /cmd_out       (no rule; promoted)
# One topic inside the file, /mux/cmd_vel, wiring teleop to cmd_relay.
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='rules_nodes', executable='teleop', name='teleop',
             remappings=[('/robo/cmd_vel', '/mux/cmd_vel')]),
        Node(package='rules_nodes', executable='cmd_relay', name='cmd_relay',
             remappings=[('/robo/cmd_vel', '/mux/cmd_vel')]),
    ])
