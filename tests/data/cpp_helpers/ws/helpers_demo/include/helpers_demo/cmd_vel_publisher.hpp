#ifndef HELPERS_DEMO__CMD_VEL_PUBLISHER_HPP_
#define HELPERS_DEMO__CMD_VEL_PUBLISHER_HPP_

#include <string>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"

namespace helpers_demo
{

// Not a node: publishes on the node it is given, on the topic it is given.
class CmdVelPublisher
{
public:
  CmdVelPublisher(rclcpp::Node::SharedPtr node, const std::string & topic)
  {
    pub_ = node->create_publisher<geometry_msgs::msg::Twist>(topic, 10);
  }

private:
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr pub_;
};

// Never given a node by anyone: its port belongs to no node.
class UnusedHelper
{
public:
  explicit UnusedHelper(rclcpp::Node::SharedPtr node)
  {
    pub_ = node->create_publisher<geometry_msgs::msg::Twist>("unused", 1);
  }

private:
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr pub_;
};

}  // namespace helpers_demo

#endif  // HELPERS_DEMO__CMD_VEL_PUBLISHER_HPP_
