#pragma once

#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace yard_pipeline
{

// Grabs frames and publishes them.
class CameraStage : public rclcpp::Node
{
public:
  explicit CameraStage(const rclcpp::NodeOptions & options);

private:
  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr frames_;
};

// Draws markers onto the frames it is given.
class MarkerStage : public rclcpp::Node
{
public:
  explicit MarkerStage(const rclcpp::NodeOptions & options);

private:
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr in_;
  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr out_;
};

// Shows the marked frames.
class DisplayStage : public rclcpp::Node
{
public:
  explicit DisplayStage(const rclcpp::NodeOptions & options);

private:
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr in_;
};

}  // namespace yard_pipeline
