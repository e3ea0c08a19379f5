#include "deep_controller/parameter_handler.hpp"

namespace deep_controller
{

ParameterHandler::ParameterHandler(const rclcpp_lifecycle::LifecycleNode::SharedPtr & node)
{
  params_.frequency = declare_or_get_parameter(node, "frequency", 20.0);
  params_.odom_topic = declare_or_get_parameter(node, "odom_topic", std::string("odom"));
  params_.speed_limit_topic = node->declare_parameter("speed_limit_topic", "speed_limit");
  node->declare_parameter("base_frame", std::string("base_link"));
  node->get_parameter("base_frame", params_.base_frame);
}

}  // namespace deep_controller
