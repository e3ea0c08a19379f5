#include "lidar_filters/crop_filter.hpp"

#include <rclcpp_components/register_node_macro.hpp>
#include <std_msgs/msg/float64.hpp>

namespace lidar_filters
{
CropFilter::CropFilter(const rclcpp::NodeOptions & options)
: Node("crop_filter", options)
{
  debug_ = std::make_unique<lidar_utils::DebugChannel>(this, "crop_filter");
  twist_input_ =
    lidar_utils::PollingInput<geometry_msgs::msg::TwistStamped>::create_subscription(
    this, "~/input/twist");
  cloud_sub_ = create_subscription<sensor_msgs::msg::PointCloud2>(
    "~/input/points", rclcpp::SensorDataQoS(),
    std::bind(&CropFilter::on_cloud, this, std::placeholders::_1));
  cloud_pub_ = create_publisher<sensor_msgs::msg::PointCloud2>("~/output/points", 1);
}

void CropFilter::on_cloud(const sensor_msgs::msg::PointCloud2::ConstSharedPtr cloud)
{
  std_msgs::msg::Float64 elapsed;
  debug_->publish<std_msgs::msg::Float64>("cycle_time_ms", elapsed);
  cloud_pub_->publish(*cloud);
  debug_->publish<std_msgs::msg::Float64>("processing_time_ms", elapsed);
  // the same name again: the same publisher, the same port
  debug_->publish<std_msgs::msg::Float64>("cycle_time_ms", elapsed);
}
}  // namespace lidar_filters

RCLCPP_COMPONENTS_REGISTER_NODE(lidar_filters::CropFilter)
