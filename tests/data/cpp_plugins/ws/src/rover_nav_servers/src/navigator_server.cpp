#include <memory>
#include <string>
#include <vector>
#include <nav_msgs/msg/odometry.hpp>
#include <pluginlib/class_loader.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include "rover_nav_core/navigator.hpp"

namespace rover_nav_servers
{
// Loads the navigators its parameters name (`navigators`, then `<id>.plugin`).
class NavigatorServer : public rclcpp_lifecycle::LifecycleNode
{
public:
  NavigatorServer()
  : rclcpp_lifecycle::LifecycleNode("navigator_server"),
    loader_("rover_nav_core", "rover_nav_core::NavigatorBase")
  {
    odom_sub_ = create_subscription<nav_msgs::msg::Odometry>(
      "odom", 10, [](nav_msgs::msg::Odometry::SharedPtr) {});
    declare_parameter("navigators", std::vector<std::string>{});
    for (const auto & id : get_parameter("navigators").as_string_array()) {
      declare_parameter(id + ".plugin", std::string());
      auto type = get_parameter(id + ".plugin").as_string();
      navigators_.push_back(loader_.createSharedInstance(type));
      navigators_.back()->on_configure(weak_from_this());
    }
  }

private:
  pluginlib::ClassLoader<rover_nav_core::NavigatorBase> loader_;
  std::vector<std::shared_ptr<rover_nav_core::NavigatorBase>> navigators_;
  rclcpp::Subscription<nav_msgs::msg::Odometry>::SharedPtr odom_sub_;
};
}  // namespace rover_nav_servers

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rover_nav_servers::NavigatorServer>();
  rclcpp::spin(node->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
