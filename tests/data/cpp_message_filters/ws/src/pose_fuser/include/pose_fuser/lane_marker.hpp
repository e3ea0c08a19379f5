#pragma once

#include <memory>
#include <string>
#include <cuda_blackboard/cuda_blackboard_publisher.hpp>
#include <cuda_blackboard/cuda_pointcloud2.hpp>
#include <image_transport/image_transport.hpp>
#include <image_transport/subscriber_filter.hpp>
#include <nav_msgs/msg/odometry.hpp>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/camera_info.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>

#include "pose_fuser/paired.hpp"

namespace pose_fuser
{
// Finds lane markings in camera images and publishes them as points, on the GPU.
class LaneMarker : public rclcpp::Node
{
public:
  explicit LaneMarker(const rclcpp::NodeOptions & options);

private:
  bool use_lidar_{false};
  std::string mode_;
  image_transport::SubscriberFilter image_sub_;
  Paired<sensor_msgs::msg::CameraInfo, nav_msgs::msg::Odometry> info_and_odometry_;
  image_transport::Publisher debug_pub_;
  std::unique_ptr<cuda_blackboard::CudaBlackboardPublisher<cuda_blackboard::CudaPointCloud2>>
    points_pub_;
  rclcpp::Subscription<sensor_msgs::msg::PointCloud2>::SharedPtr lidar_sub_;
};
}  // namespace pose_fuser
