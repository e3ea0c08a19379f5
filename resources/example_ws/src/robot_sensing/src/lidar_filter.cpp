#include "robot_sensing/lidar_filter.hpp"

#include <functional>
#include <limits>
#include <rclcpp_components/register_node_macro.hpp>

namespace robot_sensing
{

LidarFilter::LidarFilter(const rclcpp::NodeOptions & options)
: Node("lidar_filter", options)
{
  min_range_ = declare_parameter("min_range", 0.1);
  max_range_ = declare_parameter("max_range", 12.0);
  const std::string output_topic = declare_parameter("output_topic", "scan_filtered");

  filtered_pub_ = create_publisher<sensor_msgs::msg::LaserScan>(output_topic, 10);
  scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
    "scan", rclcpp::SensorDataQoS(),
    std::bind(&LidarFilter::on_scan, this, std::placeholders::_1));
}

void LidarFilter::on_scan(const sensor_msgs::msg::LaserScan::SharedPtr msg)
{
  auto filtered = *msg;
  for (auto & r : filtered.ranges) {
    if (r < min_range_ || r > max_range_) {
      r = std::numeric_limits<float>::quiet_NaN();
    }
  }
  filtered_pub_->publish(filtered);
}

}  // namespace robot_sensing

RCLCPP_COMPONENTS_REGISTER_NODE(robot_sensing::LidarFilter)
