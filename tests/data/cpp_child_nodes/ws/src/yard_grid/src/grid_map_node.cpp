#include "yard_grid/grid_map_node.hpp"

namespace yard_grid
{
namespace
{
// The node's own namespace and name, whatever the process was started with.
rclcpp::NodeOptions nestedOptions(
  const std::string & name, const std::string & parent_namespace,
  const rclcpp::NodeOptions & options)
{
  std::vector<std::string> args = options.arguments();
  args.push_back("--ros-args");
  args.push_back("-r");
  args.push_back("__ns:=" + parent_namespace + "/" + name);
  args.push_back("-r");
  args.push_back(name + ":__node:=" + name);
  return rclcpp::NodeOptions(options).arguments(args);
}
}  // namespace

GridMapNode::GridMapNode(const rclcpp::NodeOptions & options)
: rclcpp_lifecycle::LifecycleNode("grid_map", "", options),
  loader_("yard_grid", "yard_grid::GridLayer")
{
  setup();
}

GridMapNode::GridMapNode(
  const std::string & name, const std::string & parent_namespace,
  const rclcpp::NodeOptions & options)
: rclcpp_lifecycle::LifecycleNode(name, "", nestedOptions(name, parent_namespace, options)),
  loader_("yard_grid", "yard_grid::GridLayer")
{
  setup();
}

void GridMapNode::setup()
{
  grid_pub_ = create_publisher<nav_msgs::msg::OccupancyGrid>("grid", 1);
  // For the operator's view only; no node reads it.
  outline_pub_ = create_publisher<geometry_msgs::msg::PolygonStamped>("outline", 1);
  declare_parameter("layers", std::vector<std::string>{});
  for (const auto & layer : get_parameter("layers").as_string_array()) {
    auto loaded = loader_.createSharedInstance(get_parameter(layer + ".plugin").as_string());
    loaded->attach(weak_from_this(), layer);
    layers_.push_back(loaded);
  }
}
}  // namespace yard_grid
