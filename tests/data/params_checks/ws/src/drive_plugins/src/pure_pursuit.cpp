// A follower plugin: its parameters sit under the name the server loads it by.
#include <nav2_util/node_utils.hpp>
#include <pluginlib/class_list_macros.hpp>
#include "drive_core/follower.hpp"

namespace drive_plugins
{
class PurePursuit : public drive_core::Follower
{
public:
  void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name) override
  {
    auto node = parent.lock();
    plugin_name_ = name;
    nav2_util::declare_parameter_if_not_declared(
      node, plugin_name_ + ".desired_linear_vel", rclcpp::ParameterValue(0.5));
    nav2_util::declare_parameter_if_not_declared(
      node, plugin_name_ + ".lookahead_dist", rclcpp::ParameterValue(0.6));
    nav2_util::declare_parameter_if_not_declared(
      node, plugin_name_ + ".use_rotate_to_heading", rclcpp::ParameterValue(true));
  }

private:
  std::string plugin_name_;
};
}  // namespace drive_plugins

PLUGINLIB_EXPORT_CLASS(drive_plugins::PurePursuit, drive_core::Follower)
