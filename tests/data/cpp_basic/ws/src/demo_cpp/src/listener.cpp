#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

// A node defined in one file, with lambda callbacks.
class Listener : public rclcpp::Node
{
public:
  Listener()
  : Node("listener")
  {
    sub_ = create_subscription<std_msgs::msg::String>(
      "chatter", 10,
      [this](const std_msgs::msg::String & msg) {
        RCLCPP_INFO(get_logger(), "I heard: %s", msg.data.c_str());
      });
    auto on_echo = [this](std_msgs::msg::String::ConstSharedPtr msg) {
        RCLCPP_INFO(get_logger(), "echo: %s", msg->data.c_str());
      };
    echo_sub_ = this->create_subscription<std_msgs::msg::String>("echo", 10, on_echo);
  }

private:
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr echo_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Listener>());
  rclcpp::shutdown();
  return 0;
}
