#include "robot_navigation/safety_monitor.hpp"

namespace robot_navigation
{

SafetyMonitor::SafetyMonitor(rclcpp_lifecycle::LifecycleNode * node)
{
  estop_sub_ = node->create_subscription<std_msgs::msg::Bool>(
    "emergency_stop", 1,
    std::bind(&SafetyMonitor::on_emergency_stop, this, std::placeholders::_1));
}

void SafetyMonitor::on_emergency_stop(const std_msgs::msg::Bool::SharedPtr msg)
{
  stopped_ = msg->data;
}

}  // namespace robot_navigation
