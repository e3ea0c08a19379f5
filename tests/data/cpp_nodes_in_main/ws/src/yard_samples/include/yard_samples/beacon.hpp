#pragma once

#include <string>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace yard_samples
{

// A beacon whose name and topic its maker chooses.
class Beacon : public rclcpp::Node
{
public:
  Beacon(const std::string & name, const std::string & topic)
  : Node(name)
  {
    pub_ = create_publisher<std_msgs::msg::String>(topic, 10);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

}  // namespace yard_samples
