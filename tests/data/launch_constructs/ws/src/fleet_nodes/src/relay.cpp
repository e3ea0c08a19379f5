#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

namespace fleet_nodes
{
class Relay : public rclcpp::Node
{
public:
  explicit Relay(const rclcpp::NodeOptions & options)
  : Node("relay", options)
  {
    pub_ = create_publisher<std_msgs::msg::String>("out", 10);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace fleet_nodes

RCLCPP_COMPONENTS_REGISTER_NODE(fleet_nodes::Relay)
