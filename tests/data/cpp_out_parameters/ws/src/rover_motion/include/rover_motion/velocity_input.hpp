#pragma once

#include <functional>
#include <string>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"

namespace rover_motion
{

// Wraps the subscription a node listens to velocity commands with.
class VelocityInput
{
public:
  VelocityInput(
    rclcpp::Node * node, const std::string & topic,
    std::function<void(geometry_msgs::msg::Twist::SharedPtr)> callback)
  {
    sub_ = node->create_subscription<geometry_msgs::msg::Twist>(topic, 10, callback);
  }

private:
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr sub_;
};

}  // namespace rover_motion
