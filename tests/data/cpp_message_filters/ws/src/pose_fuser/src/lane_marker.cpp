#include "pose_fuser/lane_marker.hpp"

namespace pose_fuser
{
LaneMarker::LaneMarker(const rclcpp::NodeOptions & options)
: rclcpp::Node("lane_marker", options),
  info_and_odometry_(this, "~/input/camera_info", "~/input/odometry")
{
  use_lidar_ = declare_parameter<bool>("use_lidar", false);
  mode_ = declare_parameter<std::string>("mode", "camera");
  // Images come through image_transport, synchronised like message_filters subscribers.
  image_sub_.subscribe(this, "~/input/image", "raw", rclcpp::SensorDataQoS().get_rmw_qos_profile());
  // A debug picture: image_transport advertises ~/debug/lanes and one topic per plugin.
  debug_pub_ = image_transport::create_publisher(this, "~/debug/lanes");
  // The points go out through the GPU blackboard (and its negotiated ~/output/points/cuda).
  points_pub_ =
    std::make_unique<cuda_blackboard::CudaBlackboardPublisher<cuda_blackboard::CudaPointCloud2>>(
      *this, "~/output/points");
  // Only in one mode, with the lidar on: whether it exists depends on two parameters.
  if (use_lidar_ && mode_ == "fusion") {
    lidar_sub_ = create_subscription<sensor_msgs::msg::PointCloud2>(
      "~/input/lidar", rclcpp::SensorDataQoS(), [](sensor_msgs::msg::PointCloud2::ConstSharedPtr) {});
  }
}
}  // namespace pose_fuser

#include <rclcpp_components/register_node_macro.hpp>
RCLCPP_COMPONENTS_REGISTER_NODE(pose_fuser::LaneMarker)
