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

protected:
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
};
}  // namespace rover_nav_core
