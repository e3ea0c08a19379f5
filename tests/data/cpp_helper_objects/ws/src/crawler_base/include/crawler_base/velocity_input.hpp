#pragma once

#include <functional>
#include <string>
#include <geometry_msgs/msg/twist.hpp>
#include <rclcpp/rclcpp.hpp>

namespace crawler
{
// Takes the callback from its owner: the subscription is the owner's.
class VelocityInput
{
public:
  VelocityInput(
    std::shared_ptr<rclcpp::Node> & nh, const std::string & topic,
    std::function<void(geometry_msgs::msg::Twist::SharedPtr)> on_twist)
  {
    sub_ = nh->create_subscription<geometry_msgs::msg::Twist>(topic, 10, on_twist);
  }

private:
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr sub_;
};
}  // namespace crawler
