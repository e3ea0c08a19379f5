// A composable image source: one publisher on the relative topic `image`.
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace rules_components
{

class Camera : public rclcpp::Node
{
public:
  explicit Camera(const rclcpp::NodeOptions & options)
  : Node("camera", options)
  {
    image_pub_ = create_publisher<sensor_msgs::msg::Image>("image", 10);
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr image_pub_;
};

}  // namespace rules_components

RCLCPP_COMPONENTS_REGISTER_NODE(rules_components::Camera)
