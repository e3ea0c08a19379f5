#pragma once

#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>

namespace robot_sensing
{

/// Drops lidar returns outside a configurable range window.
class LidarFilter : public rclcpp::Node
{
public:
  explicit LidarFilter(const rclcpp::NodeOptions & options);

private:
  void on_scan(const sensor_msgs::msg::LaserScan::SharedPtr msg);

  double min_range_;
  double max_range_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr scan_sub_;
  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr filtered_pub_;
};

}  // namespace robot_sensing
