#include <nav_msgs/msg/odometry.hpp>
#include <nav_msgs/msg/path.hpp>
#include <std_msgs/msg/bool.hpp>
#include <std_msgs/msg/float64.hpp>
#include <pluginlib/class_list_macros.hpp>
#include <visualization_msgs/msg/marker_array.hpp>
#include "rover_nav_core/grid_controller.hpp"

namespace rover_nav_plugins
{
class PathFollower : public rover_nav_core::GridController
{
public:
  void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name) override
  {
    node_ = parent;
    auto node = parent.lock();
    plugin_name_ = name;
    grid_name_ = name;
    // Settings of this follower live under its name: `FollowPath.speed_topic`.
    speed_topic_ = node->declare_parameter(plugin_name_ + "." + "speed_topic", std::string("speed_limit"));
    speed_topic_ = joinWithParentNamespace(speed_topic_);
    speed_sub_ = node->create_subscription<std_msgs::msg::Float64>(
      speed_topic_, 1, [](std_msgs::msg::Float64::SharedPtr) {});
    readAlarmTopic(plugin_name_);
    odom_sub_ = node->create_subscription<nav_msgs::msg::Odometry>(
      node->declare_parameter(plugin_name_ + ".odom_topic", std::string("odom")), 1,
      [](nav_msgs::msg::Odometry::SharedPtr) {});
    // Under the name the server loads the plugin by, so two followers do not collide.
    plan_pub_ = node->create_publisher<nav_msgs::msg::Path>(plugin_name_ + "/local_plan", 1);
    markers_pub_ = node->create_publisher<visualization_msgs::msg::MarkerArray>("follower_markers", 1);
  }

protected:
  void initializeAlarm(const std::string & topic) override
  {
    alarm_topic_ = joinWithParentNamespace(topic);
    alarm_sub_ = node_.lock()->create_subscription<std_msgs::msg::Bool>(
      alarm_topic_, 1, [](std_msgs::msg::Bool::SharedPtr) {});
  }

private:
  rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr alarm_sub_;
  std::string plugin_name_;
  std::string speed_topic_;
  rclcpp::Subscription<std_msgs::msg::Float64>::SharedPtr speed_sub_;
  rclcpp::Subscription<nav_msgs::msg::Odometry>::SharedPtr odom_sub_;
  rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::Path>::SharedPtr plan_pub_;
  rclcpp_lifecycle::LifecyclePublisher<visualization_msgs::msg::MarkerArray>::SharedPtr markers_pub_;
};
}  // namespace rover_nav_plugins

PLUGINLIB_EXPORT_CLASS(rover_nav_plugins::PathFollower, rover_nav_core::Controller)
