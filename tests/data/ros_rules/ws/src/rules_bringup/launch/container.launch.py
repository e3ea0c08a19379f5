# Rule: a component container is deployment, not architecture.
#
# Expected:
#   parts camera (rules_components::Camera) and detector (rules_components::Detector),
#   each recording container vision_container; vision_container itself is NOT a part;
#   topic /image wires camera to detector inside the file;
#   detector's /detections has no consumer here, so it is promoted (one boundary port).
from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    container = ComposableNodeContainer(
        name='vision_container',
        namespace='',
        package='rclcpp_components',
        executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='rules_components', plugin='rules_components::Camera',
                           name='camera'),
            ComposableNode(package='rules_components', plugin='rules_components::Detector',
                           name='detector'),
        ])
    return LaunchDescription([container])
