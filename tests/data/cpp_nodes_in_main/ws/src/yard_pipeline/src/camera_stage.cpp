#include "yard_pipeline/stages.hpp"

#include "rclcpp_components/register_node_macro.hpp"

namespace yard_pipeline
{

CameraStage::CameraStage(const rclcpp::NodeOptions & options)
: Node("camera", options)
{
  frames_ = create_publisher<sensor_msgs::msg::Image>("frames", 5);
}

}  // namespace yard_pipeline

RCLCPP_COMPONENTS_REGISTER_NODE(yard_pipeline::CameraStage)
