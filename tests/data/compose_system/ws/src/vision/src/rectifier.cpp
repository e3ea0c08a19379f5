#include <string>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace vision
{

class Rectifier : public rclcpp::Node
{
public:
  explicit Rectifier(const rclcpp::NodeOptions & options)
  : Node("rectifier", options)
  {
    const std::string output_topic = declare_parameter<std::string>("output_topic", "image_rect");
    image_sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image_raw", 10, std::bind(&Rectifier::on_image, this, std::placeholders::_1));
    rect_pub_ = create_publisher<sensor_msgs::msg::Image>(output_topic, 10);
  }

private:
  void on_image(const sensor_msgs::msg::Image & msg) { rect_pub_->publish(msg); }

  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr image_sub_;
  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr rect_pub_;
};

}  // namespace vision

RCLCPP_COMPONENTS_REGISTER_NODE(vision::Rectifier)
