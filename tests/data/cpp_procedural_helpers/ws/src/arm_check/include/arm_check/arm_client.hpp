#pragma once

#include <memory>
#include <string>

#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <std_srvs/srv/trigger.hpp>

namespace arm_check
{

/// Talks to one arm's driver, whose services live under the arm's name.
class ArmClient
{
public:
  ArmClient(const rclcpp::Node::SharedPtr & node, const std::string & arm);
  bool home();

private:
  rclcpp::Node::SharedPtr node_;
  rclcpp::Client<std_srvs::srv::Trigger>::SharedPtr home_client_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr log_pub_;
};

}  // namespace arm_check
