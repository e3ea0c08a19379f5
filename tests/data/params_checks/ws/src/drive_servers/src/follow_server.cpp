// Loads follower plugins named by its parameters, the way a controller server does.
#include <nav2_util/node_utils.hpp>
#include <pluginlib/class_loader.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include "drive_core/follower.hpp"

namespace drive_servers
{
class FollowServer : public rclcpp_lifecycle::LifecycleNode
{
public:
  FollowServer()
  : rclcpp_lifecycle::LifecycleNode("follow_server")
  {
    declare_parameter("controller_frequency", 20.0);
    declare_parameter("follower_plugins", std::vector<std::string>{"FollowPath"});
  }

  void on_configure()
  {
    auto node = shared_from_this();
    for (const auto & id : follower_ids_) {
      nav2_util::declare_parameter_if_not_declared(
        node, id + ".plugin", rclcpp::ParameterValue(std::string("")));
    }
  }

private:
  std::vector<std::string> follower_ids_;
};
}  // namespace drive_servers

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<drive_servers::FollowServer>();
  rclcpp::spin(node->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
