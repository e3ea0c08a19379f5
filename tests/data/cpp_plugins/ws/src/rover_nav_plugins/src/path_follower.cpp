#include <nav_msgs/msg/path.hpp>
#include <pluginlib/class_list_macros.hpp>
#include <visualization_msgs/msg/marker_array.hpp>
#include "rover_nav_core/controller.hpp"

namespace rover_nav_plugins
{
class PathFollower : public rover_nav_core::Controller
{
public:
  void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name) override
  {
    auto node = parent.lock();
    plugin_name_ = name;
    // Under the name the server loads the plugin by, so two followers do not collide.
    plan_pub_ = node->create_publisher<nav_msgs::msg::Path>(plugin_name_ + "/local_plan", 1);
    markers_pub_ = node->create_publisher<visualization_msgs::msg::MarkerArray>("follower_markers", 1);
  }

private:
  std::string plugin_name_;
  rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::Path>::SharedPtr plan_pub_;
  rclcpp_lifecycle::LifecyclePublisher<visualization_msgs::msg::MarkerArray>::SharedPtr markers_pub_;
};
}  // namespace rover_nav_plugins

PLUGINLIB_EXPORT_CLASS(rover_nav_plugins::PathFollower, rover_nav_core::Controller)
