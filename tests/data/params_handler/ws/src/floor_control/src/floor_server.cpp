// Hosts the cleaning controllers its parameters name.
#include <rclcpp_lifecycle/lifecycle_node.hpp>

namespace floor_control
{
class FloorServer : public rclcpp_lifecycle::LifecycleNode
{
public:
  FloorServer()
  : rclcpp_lifecycle::LifecycleNode("floor_server")
  {
    declare_parameter("controller_plugins", std::vector<std::string>{"Sweep"});
  }
};
}  // namespace floor_control

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<floor_control::FloorServer>();
  rclcpp::spin(node->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
