#include <memory>
#include <string>

#include <rclcpp/rclcpp.hpp>

#include "arm_check/arm_client.hpp"

// No node class: main makes the node and hands it to one client per arm. Both clients create
// their ports at the same lines; the program has each port once.
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("arm_check");
  arm_check::ArmClient left(node, "left_arm");
  arm_check::ArmClient right(node, "right_arm");
  // The raw log's type is whatever the command line names: no type the code can tell.
  const std::string raw_type = argc > 1 ? argv[1] : std::string();
  auto raw_log = node->create_generic_publisher("raw_log", raw_type, rclcpp::QoS(10));
  const bool ok = left.home() && right.home();
  rclcpp::shutdown();
  return ok ? 0 : 1;
}
