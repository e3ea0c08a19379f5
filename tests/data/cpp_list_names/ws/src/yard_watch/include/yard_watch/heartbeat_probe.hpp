#pragma once

#include <string>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/header.hpp"
#include "std_srvs/srv/trigger.hpp"

namespace yard_watch
{

// Watches one node: asks it to answer on `<target>/ping` and listens to `<target>/heartbeat`.
class HeartbeatProbe
{
public:
  HeartbeatProbe(const std::string & target, rclcpp::Node * node)
  : target_(target)
  {
    ping_client_ = node->create_client<std_srvs::srv::Trigger>(target + "/ping");
    beat_sub_ = node->create_subscription<std_msgs::msg::Header>(
      target + "/heartbeat", 10,
      [this](std_msgs::msg::Header::SharedPtr) { ++beats_; });
  }

private:
  std::string target_;
  int beats_ = 0;
  rclcpp::Client<std_srvs::srv::Trigger>::SharedPtr ping_client_;
  rclcpp::Subscription<std_msgs::msg::Header>::SharedPtr beat_sub_;
};

}  // namespace yard_watch
