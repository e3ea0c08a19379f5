#include <memory>
#include <string>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rover_motion/velocity_input.hpp"
#include "std_msgs/msg/string.hpp"

namespace rover_motion
{

class SpeedGuard : public rclcpp::Node
{
public:
  SpeedGuard()
  : Node("speed_guard")
  {
    std::string input_topic;
    std::string output_topic;
    std::string report_topic;
    readTopics(input_topic, output_topic, report_topic);

    input_ = std::make_unique<VelocityInput>(
      this, input_topic, [this](geometry_msgs::msg::Twist::SharedPtr msg) {
        output_pub_->publish(*msg);
      });
    output_pub_ = create_publisher<geometry_msgs::msg::Twist>(output_topic, 10);
    report_pub_ = create_publisher<std_msgs::msg::String>(report_topic, 10);

    // A local handed to a function that only reads it keeps no name of its own.
    std::string label;
    logLabel(label);
    label_pub_ = create_publisher<std_msgs::msg::String>(label, 10);
  }

private:
  void readTopics(std::string & input, std::string & output, std::string & report)
  {
    input = declare_parameter("input_topic", std::string("cmd_vel_smoothed"));
    output = declare_parameter("output_topic", std::string("cmd_vel"));
    report = "~/" + declare_parameter("report_name", std::string("report"));
  }

  void logLabel(const std::string & label)
  {
    RCLCPP_INFO(get_logger(), "%s", label.c_str());
  }

  std::unique_ptr<VelocityInput> input_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr output_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr report_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr label_pub_;
};

}  // namespace rover_motion

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<rover_motion::SpeedGuard>());
  rclcpp::shutdown();
  return 0;
}
