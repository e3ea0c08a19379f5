#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "std_msgs/msg/string.hpp"

namespace helpers_demo
{

// A component that owns its node instead of deriving from rclcpp::Node.
class Bridge
{
public:
  explicit Bridge(const rclcpp::NodeOptions & options)
  : node_(std::make_shared<rclcpp::Node>("bridge", options))
  {
    sub_ = node_->create_subscription<std_msgs::msg::String>(
      "in", 10, [this](std_msgs::msg::String::ConstSharedPtr msg) {pub_->publish(*msg);});
    pub_ = node_->create_publisher<std_msgs::msg::String>("out", 10);
  }

  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr get_node_base_interface() const
  {
    return node_->get_node_base_interface();
  }

private:
  rclcpp::Node::SharedPtr node_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

}  // namespace helpers_demo

RCLCPP_COMPONENTS_REGISTER_NODE(helpers_demo::Bridge)
