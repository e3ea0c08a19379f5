// A gripper whose parameters come from a generated listener, not from declare_parameter calls.
#include <control_msgs/msg/gripper_command.hpp>
#include <rclcpp/rclcpp.hpp>
#include "gripper_parameters.hpp"

namespace arm_controllers
{
class GripperNode : public rclcpp::Node
{
public:
  GripperNode()
  : Node("gripper_node"),
    listener_(std::make_shared<gripper_node::ParamListener>(get_node_parameters_interface()))
  {
    params_ = listener_->get_params();
    command_sub_ = create_subscription<control_msgs::msg::GripperCommand>(
      "gripper/command", 10, [](control_msgs::msg::GripperCommand::ConstSharedPtr) {});
  }

private:
  std::shared_ptr<gripper_node::ParamListener> listener_;
  gripper_node::Params params_;
  rclcpp::Subscription<control_msgs::msg::GripperCommand>::SharedPtr command_sub_;
};
}  // namespace arm_controllers

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<arm_controllers::GripperNode>());
  rclcpp::shutdown();
  return 0;
}
