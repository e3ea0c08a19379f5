// A composable detector: reads `image`, writes `detections` (both relative).
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "vision_msgs/msg/detection2_d_array.hpp"

namespace rules_components
{

class Detector : public rclcpp::Node
{
public:
  explicit Detector(const rclcpp::NodeOptions & options)
  : Node("detector", options)
  {
    image_sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image", 10, std::bind(&Detector::on_image, this, std::placeholders::_1));
    detections_pub_ = create_publisher<vision_msgs::msg::Detection2DArray>("detections", 10);
  }

private:
  void on_image(const sensor_msgs::msg::Image &)
  {
    detections_pub_->publish(vision_msgs::msg::Detection2DArray());
  }

  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr image_sub_;
  rclcpp::Publisher<vision_msgs::msg::Detection2DArray>::SharedPtr detections_pub_;
};

}  // namespace rules_components

RCLCPP_COMPONENTS_REGISTER_NODE(rules_components::Detector)
