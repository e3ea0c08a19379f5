#pragma once
#include <string>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

namespace drive_core
{
class Follower
{
public:
  virtual ~Follower() = default;
  virtual void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name) = 0;
};
}  // namespace drive_core
