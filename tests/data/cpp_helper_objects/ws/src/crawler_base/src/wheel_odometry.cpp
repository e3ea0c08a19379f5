#include "crawler_base/wheel_odometry.hpp"

namespace crawler
{
WheelOdometry::WheelOdometry(std::shared_ptr<rclcpp::Node> & nh, double wheel_radius)
: nh_(nh), wheel_radius_(wheel_radius)
{
  auto qos = rclcpp::QoS(rclcpp::KeepLast(10));
  odom_pub_ = nh_->create_publisher<nav_msgs::msg::Odometry>("odom", qos);
  use_imu_ = nh_->declare_parameter("odometry.use_imu", false);
  if (use_imu_) {
    // Wheel and IMU readings are paired by a synchronizer, not by a callback each.
    imu_filter_ = std::make_shared<message_filters::Subscriber<sensor_msgs::msg::Imu>>(nh_, "imu");
  } else {
    joints_sub_ = nh_->create_subscription<sensor_msgs::msg::JointState>(
      "joint_states", qos,
      std::bind(&WheelOdometry::on_joints, this, std::placeholders::_1));
  }
  reset_srv_ = nh_->create_service<std_srvs::srv::Trigger>(
    "reset_odometry",
    std::bind(&WheelOdometry::on_reset, this, std::placeholders::_1, std::placeholders::_2));
}

void WheelOdometry::on_joints(const sensor_msgs::msg::JointState::SharedPtr) {}

void WheelOdometry::on_reset(
  const std::shared_ptr<std_srvs::srv::Trigger::Request>,
  std::shared_ptr<std_srvs::srv::Trigger::Response> response)
{
  response->success = true;
}
}  // namespace crawler
