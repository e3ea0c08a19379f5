#include <memory>
#include <string>
#include <vector>
#include <geometry_msgs/msg/twist.hpp>
#include <nav_msgs/msg/occupancy_grid.hpp>
#include <pluginlib/class_loader.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include "rover_nav_core/grid_controller.hpp"

namespace rover_nav_servers
{
class FollowServer : public rclcpp_lifecycle::LifecycleNode
{
public:
  FollowServer()
  : rclcpp_lifecycle::LifecycleNode("follow_server"),
    loader_("rover_nav_core", "rover_nav_core::Controller")
  {
    cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel", 10);
    declare_parameter("controller_plugins", std::vector<std::string>{});
    for (const auto & id : get_parameter("controller_plugins").as_string_array()) {
      auto controller = loader_.createSharedInstance(get_parameter(id + ".plugin").as_string());
      controller->configure(weak_from_this(), id);
      controllers_.push_back(controller);
    }
    // Each controller that keeps a grid has it shown under the controller's own name.
    for (auto & controller : controllers_) {
      auto grid = std::dynamic_pointer_cast<rover_nav_core::GridController>(controller);
      if (grid != nullptr) {
        grid_pubs_.push_back(
          create_publisher<nav_msgs::msg::OccupancyGrid>(controller->getName() + "/grid", 1));
      }
    }
  }

private:
  pluginlib::ClassLoader<rover_nav_core::Controller> loader_;
  std::vector<std::shared_ptr<rover_nav_core::Controller>> controllers_;
  rclcpp_lifecycle::LifecyclePublisher<geometry_msgs::msg::Twist>::SharedPtr cmd_pub_;
  std::vector<rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::OccupancyGrid>::SharedPtr>
  grid_pubs_;
};
}  // namespace rover_nav_servers

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rover_nav_servers::FollowServer>();
  rclcpp::spin(node->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
