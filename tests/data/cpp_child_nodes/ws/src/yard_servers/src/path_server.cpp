#include <memory>
#include <nav_msgs/msg/path.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include "yard_grid/grid_map_node.hpp"

namespace yard_servers
{
// Plans on a grid map of its own, which runs as a node beside it in the same process.
class PathServer : public rclcpp_lifecycle::LifecycleNode
{
public:
  explicit PathServer(const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : rclcpp_lifecycle::LifecycleNode("path_server", "", options)
  {
    grid_ = std::make_shared<yard_grid::GridMapNode>(
      "world_grid", std::string{get_namespace()}, options);
    plan_pub_ = create_publisher<nav_msgs::msg::Path>("plan", 1);
  }

private:
  std::shared_ptr<yard_grid::GridMapNode> grid_;
  rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::Path>::SharedPtr plan_pub_;
};
}  // namespace yard_servers

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<yard_servers::PathServer>();
  rclcpp::spin(node->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
