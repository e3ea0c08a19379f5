#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

void on_command(const std_msgs::msg::String::SharedPtr msg)
{
  (void)msg;
}

// No node class: the node is built in main and used through a pointer.
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("old_school");
  auto pub = node->create_publisher<std_msgs::msg::String>("status", 10);
  auto sub = node->create_subscription<std_msgs::msg::String>("command", 10, on_command);
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
