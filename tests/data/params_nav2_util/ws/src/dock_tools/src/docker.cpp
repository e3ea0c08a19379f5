// Drives onto a charger; its parameters come from navigation2's declaring helpers.
#include <nav2_util/node_utils.hpp>
#include <rcl_interfaces/msg/parameter_descriptor.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

namespace dock_tools
{
class Docker : public rclcpp_lifecycle::LifecycleNode
{
public:
  Docker()
  : rclcpp_lifecycle::LifecycleNode("docker")
  {
  }

  CallbackReturn on_configure(const rclcpp_lifecycle::State &) override
  {
    auto node = shared_from_this();
    nav2_util::declare_parameter_if_not_declared(
      node, "approach_speed", rclcpp::ParameterValue(0.15));
    nav2_util::declare_parameter_if_not_declared(
      node, "dock_frame", rclcpp::ParameterValue(std::string("dock")));
    rcl_interfaces::msg::ParameterDescriptor retries;
    retries.description = "Attempts before giving up";
    nav2_util::declare_parameter_if_not_declared(
      node, "max_retries", rclcpp::ParameterValue(3), retries);

    staging_offset_ = nav2_util::declare_or_get_parameter(node, "staging_offset", 0.7);
    charger_id_ = nav2_util::declare_or_get_parameter<std::string>(
      node, "charger_id", rclcpp::ParameterType::PARAMETER_STRING);
    return CallbackReturn::SUCCESS;
  }

private:
  double staging_offset_{0.0};
  std::string charger_id_;
};
}  // namespace dock_tools

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<dock_tools::Docker>();
  rclcpp::spin(node->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
