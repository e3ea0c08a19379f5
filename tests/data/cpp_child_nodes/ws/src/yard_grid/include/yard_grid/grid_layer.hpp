#pragma once

#include <string>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

namespace yard_grid
{
// What a grid-map node loads, by the names its `layers` parameter lists.
class GridLayer
{
public:
  virtual ~GridLayer() = default;
  virtual void attach(const rclcpp_lifecycle::LifecycleNode::WeakPtr & node, std::string name) = 0;
};
}  // namespace yard_grid
