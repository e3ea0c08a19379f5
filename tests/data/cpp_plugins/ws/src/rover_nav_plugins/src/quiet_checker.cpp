#include <pluginlib/class_list_macros.hpp>
#include "rover_nav_core/controller.hpp"

namespace rover_nav_plugins
{
// Only computes: no ports, so no classifier of its own.
class QuietChecker : public rover_nav_core::Controller
{
public:
  void configure(const rclcpp_lifecycle::LifecycleNode::WeakPtr &, std::string name) override
  {
    name_ = name;
  }

private:
  std::string name_;
};
}  // namespace rover_nav_plugins

PLUGINLIB_EXPORT_CLASS(rover_nav_plugins::QuietChecker, rover_nav_core::Controller)
