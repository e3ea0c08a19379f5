#pragma once

#include <atomic>

#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <std_msgs/msg/bool.hpp>

namespace robot_navigation
{

/// Not a node: watches the emergency stop through the node handle it is given.
class SafetyMonitor
{
public:
  explicit SafetyMonitor(rclcpp_lifecycle::LifecycleNode * node);
  bool stopped() const {return stopped_;}

private:
  void on_emergency_stop(const std_msgs::msg::Bool::SharedPtr msg);

  std::atomic<bool> stopped_{false};
  rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr estop_sub_;
};

}  // namespace robot_navigation
