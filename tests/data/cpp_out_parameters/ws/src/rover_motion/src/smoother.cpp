#include <memory>
#include <string>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"

namespace rover_motion
{

class Smoother : public rclcpp::Node
{
public:
  Smoother()
  : Node("smoother")
  {
    const std::string out = declare_parameter("smoothed_topic", std::string("cmd_vel_smoothed"));
    smoothed_pub_ = create_publisher<geometry_msgs::msg::Twist>(out, 10);
    raw_sub_ = create_subscription<geometry_msgs::msg::Twist>(
      "cmd_vel_raw", 10, [this](geometry_msgs::msg::Twist::SharedPtr msg) {
        smoothed_pub_->publish(*msg);
      });
  }

private:
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr smoothed_pub_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr raw_sub_;
};

}  // namespace rover_motion

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<rover_motion::Smoother>());
  rclcpp::shutdown();
  return 0;
}
