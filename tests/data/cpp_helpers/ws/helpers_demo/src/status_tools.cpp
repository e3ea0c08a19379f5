#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace helpers_demo
{

// A free helper function: its port belongs to whoever hands it a node.
void add_status_publisher(rclcpp::Node::SharedPtr node, const std::string & topic)
{
  node->create_publisher<std_msgs::msg::String>(topic, 1);
}

// A node factory: the node it returns is made for others, it is no node of its own.
rclcpp::Node::SharedPtr make_internal_node()
{
  auto node = rclcpp::Node::make_shared("_internal");
  return node;
}

}  // namespace helpers_demo

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("status_tool");
  helpers_demo::add_status_publisher(node, "status");
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
