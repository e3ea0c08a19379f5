#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "std_srvs/srv/trigger.hpp"
#include "vision_msgs/msg/detection2_d_array.hpp"

namespace vision
{

class Detector : public rclcpp::Node
{
public:
  explicit Detector(const rclcpp::NodeOptions & options)
  : Node("detector", options)
  {
    image_sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image_rect", 10, std::bind(&Detector::on_image, this, std::placeholders::_1));
    detections_pub_ = create_publisher<vision_msgs::msg::Detection2DArray>("/detections", 10);
    calibration_client_ = create_client<std_srvs::srv::Trigger>("get_calibration");
  }

private:
  void on_image(const sensor_msgs::msg::Image &) {}

  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr image_sub_;
  rclcpp::Publisher<vision_msgs::msg::Detection2DArray>::SharedPtr detections_pub_;
  rclcpp::Client<std_srvs::srv::Trigger>::SharedPtr calibration_client_;
};

}  // namespace vision

RCLCPP_COMPONENTS_REGISTER_NODE(vision::Detector)
