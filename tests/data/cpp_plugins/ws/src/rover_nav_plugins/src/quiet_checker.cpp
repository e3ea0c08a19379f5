#include <pluginlib/class_list_macros.hpp>
#include "rover_nav_core/controller.hpp"

namespace rover_nav_plugins
{
// Only computes: no ports. It reads its alarm setting like every controller, so it is a
// classifier with a parameter and no ports.
class QuietChecker : public rover_nav_core::Controller
{
public:
  void configure(const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name) override
  {
    node_ = parent;
    name_ = name;
    readAlarmTopic(name_);
  }

protected:
  void initializeAlarm(const std::string &) override {}

private:
  std::string name_;
};
}  // namespace rover_nav_plugins

PLUGINLIB_EXPORT_CLASS(rover_nav_plugins::QuietChecker, rover_nav_core::Controller)
