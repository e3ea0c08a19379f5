#pragma once

#include <string>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

namespace rover_nav_core
{
class Controller
{
public:
  virtual ~Controller() = default;
  virtual void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name) = 0;
  virtual std::string getName() const {return "controller";}

  // Starts listening for alarms on the topic the plugin's settings name.
  void activate()
  {
    initializeAlarm(alarm_topic_);
  }

protected:
  void readAlarmTopic(const std::string & name)
  {
    auto node = node_.lock();
    alarm_topic_ = node->declare_parameter(name + "." + "alarm_topic", std::string("alarm"));
  }

  virtual void initializeAlarm(const std::string & topic) = 0;

  // A relative topic is taken one namespace above the node's own.
  std::string joinWithParentNamespace(const std::string & topic)
  {
    auto node = node_.lock();
    if (!node || topic.empty() || topic[0] == '/') {
      return topic;
    }
    const std::string ns = node->get_namespace();
    return ns.substr(0, ns.rfind('/')) + "/" + topic;
  }

  rclcpp_lifecycle::LifecycleNode::WeakPtr node_;
  std::string alarm_topic_;
};
}  // namespace rover_nav_core
