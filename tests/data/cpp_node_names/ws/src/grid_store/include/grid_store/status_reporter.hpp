#pragma once

#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

namespace grid_store
{
// Reports a node's state on a topic named after the node it is given.
class StatusReporter
{
public:
  explicit StatusReporter(rclcpp::Node * node)
  {
    pub_ = node->create_publisher<std_msgs::msg::String>(
      std::string(node->get_name()) + "/status", 1);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace grid_store
