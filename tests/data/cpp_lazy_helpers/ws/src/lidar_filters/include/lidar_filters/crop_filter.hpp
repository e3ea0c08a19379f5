#pragma once

#include <memory>
#include <geometry_msgs/msg/twist_stamped.hpp>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/imu.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>
// The helpers moved to lidar_utils::; this workspace still has them as
// lidar::common_utils:: (one class of each name), and they are taken by name.
#include "lidar/common_utils/debug_channel.hpp"
#include "lidar/common_utils/polling_input.hpp"

namespace lidar_filters
{
class CropFilter : public rclcpp::Node
{
public:
  explicit CropFilter(const rclcpp::NodeOptions & options);

private:
  void on_cloud(const sensor_msgs::msg::PointCloud2::ConstSharedPtr cloud);

  std::unique_ptr<lidar_utils::DebugChannel> debug_;
  lidar_utils::PollingInput<geometry_msgs::msg::TwistStamped>::SharedPtr twist_input_;
  // Built in the class body with the node.
  lidar_utils::PollingInput<sensor_msgs::msg::Imu> imu_input_{this, "~/input/imu"};
  rclcpp::Subscription<sensor_msgs::msg::PointCloud2>::SharedPtr cloud_sub_;
  rclcpp::Publisher<sensor_msgs::msg::PointCloud2>::SharedPtr cloud_pub_;
};
}  // namespace lidar_filters
