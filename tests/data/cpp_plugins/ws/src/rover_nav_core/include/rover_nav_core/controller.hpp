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
};
}  // namespace rover_nav_core
