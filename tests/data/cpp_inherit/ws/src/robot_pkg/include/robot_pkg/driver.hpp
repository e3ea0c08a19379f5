#ifndef ROBOT_PKG__DRIVER_HPP_
#define ROBOT_PKG__DRIVER_HPP_

#include "base_pkg/managed_node.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "nav_msgs/msg/odometry.hpp"

namespace robot_pkg
{

using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

class Driver : public base_pkg::ManagedNode
{
public:
  Driver();
  CallbackReturn on_configure(const rclcpp_lifecycle::State & state) override;

protected:
  void on_cmd_vel(const geometry_msgs::msg::Twist::SharedPtr msg);

  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr cmd_sub_;
  rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::Odometry>::SharedPtr odom_pub_;
};

// Second level: still a lifecycle node, through Driver.
class SafeDriver : public Driver
{
public:
  SafeDriver();

private:
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr stop_pub_;
};

}  // namespace robot_pkg

#endif  // ROBOT_PKG__DRIVER_HPP_
