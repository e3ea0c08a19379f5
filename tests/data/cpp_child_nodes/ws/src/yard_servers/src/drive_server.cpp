#include <memory>
#include <nav_msgs/msg/path.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include "yard_grid/grid_map_node.hpp"

namespace yard_servers
{
// Follows the plan on a smaller grid map of its own.
class DriveServer : public rclcpp_lifecycle::LifecycleNode
{
public:
  DriveServer()
  : rclcpp_lifecycle::LifecycleNode("drive_server")
  {
    const std::string grid_name = "near_grid";
    grid_ = std::make_unique<yard_grid::GridMapNode>(grid_name, get_namespace());
    plan_sub_ = create_subscription<nav_msgs::msg::Path>(
      "plan", 1, [](nav_msgs::msg::Path::ConstSharedPtr) {});
  }

private:
  std::unique_ptr<yard_grid::GridMapNode> grid_;
  rclcpp::Subscription<nav_msgs::msg::Path>::SharedPtr plan_sub_;
};
}  // namespace yard_servers

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<yard_servers::DriveServer>();
  rclcpp::spin(node->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
