#pragma once

#include <memory>
#include <geometry_msgs/msg/pose_stamped.hpp>
#include <message_filters/subscriber.h>
#include <message_filters/sync_policies/approximate_time.h>
#include <message_filters/synchronizer.h>
#include <nav_msgs/msg/odometry.hpp>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/imu.hpp>

namespace pose_fuser
{
using Imu = sensor_msgs::msg::Imu;
using Odometry = nav_msgs::msg::Odometry;

// Pairs an IMU reading with the odometry of the same moment and publishes the fused pose.
class PoseFuser : public rclcpp::Node
{
public:
  explicit PoseFuser(const rclcpp::NodeOptions & options);

private:
  using SyncPolicy = message_filters::sync_policies::ApproximateTime<Imu, Odometry>;
  void onPair(const Imu::ConstSharedPtr & imu, const Odometry::ConstSharedPtr & odom);

  bool use_odometry_{true};
  message_filters::Subscriber<Imu> imu_sub_;
  message_filters::Subscriber<Odometry> odom_sub_;
  std::shared_ptr<message_filters::Synchronizer<SyncPolicy>> sync_;
  rclcpp::Publisher<geometry_msgs::msg::PoseStamped>::SharedPtr pose_pub_;
};
}  // namespace pose_fuser
