#pragma once

#include <memory>
#include <string>
#include <vector>
#include <geometry_msgs/msg/polygon_stamped.hpp>
#include <nav_msgs/msg/occupancy_grid.hpp>
#include <pluginlib/class_loader.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include "yard_grid/grid_layer.hpp"

namespace yard_grid
{
// A grid map that runs as a node of its own, or inside a server that needs one: then it is
// named by the server and lives in a namespace of that name under the server's namespace.
class GridMapNode : public rclcpp_lifecycle::LifecycleNode
{
public:
  explicit GridMapNode(const rclcpp::NodeOptions & options = rclcpp::NodeOptions());
  GridMapNode(
    const std::string & name, const std::string & parent_namespace,
    const rclcpp::NodeOptions & options = rclcpp::NodeOptions());

private:
  void setup();

  pluginlib::ClassLoader<GridLayer> loader_;
  std::vector<std::shared_ptr<GridLayer>> layers_;
  rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::OccupancyGrid>::SharedPtr grid_pub_;
  rclcpp_lifecycle::LifecyclePublisher<geometry_msgs::msg::PolygonStamped>::SharedPtr outline_pub_;
};
}  // namespace yard_grid
