#pragma once

#include <memory>
#include <message_filters/subscriber.h>
#include <nav_msgs/msg/odometry.hpp>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/imu.hpp>
#include <sensor_msgs/msg/joint_state.hpp>
#include <std_srvs/srv/trigger.hpp>

namespace crawler
{
// Keeps the node handle in a member and creates everything through it.
class WheelOdometry
{
public:
  WheelOdometry(std::shared_ptr<rclcpp::Node> & nh, double wheel_radius);

private:
  void on_joints(const sensor_msgs::msg::JointState::SharedPtr msg);
  void on_reset(
    const std::shared_ptr<std_srvs::srv::Trigger::Request>,
    std::shared_ptr<std_srvs::srv::Trigger::Response>);

  std::shared_ptr<rclcpp::Node> nh_;
  double wheel_radius_;
  bool use_imu_{false};
  std::shared_ptr<message_filters::Subscriber<sensor_msgs::msg::Imu>> imu_filter_;
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr odom_pub_;
  rclcpp::Subscription<sensor_msgs::msg::JointState>::SharedPtr joints_sub_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr reset_srv_;
};
}  // namespace crawler
