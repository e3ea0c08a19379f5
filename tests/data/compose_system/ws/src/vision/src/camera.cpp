#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "std_msgs/msg/empty.hpp"
#include "std_srvs/srv/set_bool.hpp"

namespace vision
{

class Camera : public rclcpp::Node
{
public:
  Camera()
  : Node("camera")
  {
    const bool enable_exposure = declare_parameter("enable_exposure", false);
    image_pub_ = create_publisher<sensor_msgs::msg::Image>("image_raw", 10);
    trigger_sub_ = create_subscription<std_msgs::msg::Empty>(
      "trigger", 10, std::bind(&Camera::on_trigger, this, std::placeholders::_1));
    if (enable_exposure) {
      exposure_srv_ = create_service<std_srvs::srv::SetBool>(
        "~/set_exposure",
        std::bind(&Camera::handle_exposure, this, std::placeholders::_1, std::placeholders::_2));
    }
  }

private:
  void on_trigger(const std_msgs::msg::Empty &) {}
  void handle_exposure(
    const std::shared_ptr<std_srvs::srv::SetBool::Request>,
    std::shared_ptr<std_srvs::srv::SetBool::Response>) {}

  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr image_pub_;
  rclcpp::Subscription<std_msgs::msg::Empty>::SharedPtr trigger_sub_;
  rclcpp::Service<std_srvs::srv::SetBool>::SharedPtr exposure_srv_;
};

}  // namespace vision

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<vision::Camera>());
  rclcpp::shutdown();
  return 0;
}
