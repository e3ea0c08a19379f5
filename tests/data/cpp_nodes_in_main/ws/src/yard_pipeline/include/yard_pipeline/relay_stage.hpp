#pragma once

#include <string>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace yard_pipeline
{

// Passes frames from one topic to another; whoever builds it says which.
class RelayStage : public rclcpp::Node
{
public:
  RelayStage(
    const std::string & input, const std::string & output,
    const std::string & node_name = "relay");

private:
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr in_;
  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr out_;
};

}  // namespace yard_pipeline
