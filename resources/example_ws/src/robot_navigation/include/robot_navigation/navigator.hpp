#pragma once

#include <memory>

#include <geometry_msgs/msg/twist.hpp>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <robot_interfaces/action/navigate.hpp>
#include <robot_interfaces/srv/set_mode.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>

#include "robot_navigation/safety_monitor.hpp"

namespace robot_navigation
{

/// Drives the robot to goal positions while avoiding obstacles seen in the filtered scan.
class Navigator : public rclcpp_lifecycle::LifecycleNode
{
public:
  using Navigate = robot_interfaces::action::Navigate;
  using GoalHandle = rclcpp_action::ServerGoalHandle<Navigate>;
  using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

  explicit Navigator(const rclcpp::NodeOptions & options = rclcpp::NodeOptions());

  CallbackReturn on_configure(const rclcpp_lifecycle::State & state) override;
  CallbackReturn on_activate(const rclcpp_lifecycle::State & state) override;

private:
  rclcpp_action::GoalResponse handle_goal(
    const rclcpp_action::GoalUUID & uuid, std::shared_ptr<const Navigate::Goal> goal);
  rclcpp_action::CancelResponse handle_cancel(const std::shared_ptr<GoalHandle> goal_handle);
  void handle_accepted(const std::shared_ptr<GoalHandle> goal_handle);
  void on_scan(const sensor_msgs::msg::LaserScan::SharedPtr msg);

  std::unique_ptr<SafetyMonitor> safety_;
  rclcpp_lifecycle::LifecyclePublisher<geometry_msgs::msg::Twist>::SharedPtr cmd_pub_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr scan_sub_;
  rclcpp::Client<robot_interfaces::srv::SetMode>::SharedPtr mode_client_;
  rclcpp_action::Server<Navigate>::SharedPtr navigate_server_;
};

}  // namespace robot_navigation
