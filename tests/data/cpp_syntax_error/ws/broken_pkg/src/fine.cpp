#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

class Fine : public rclcpp::Node
{
public:
  Fine()
  : Node("fine")
  {
    sub_ = create_subscription<std_msgs::msg::String>(
      "alive", 10, [](std_msgs::msg::String::ConstSharedPtr) {});
  }

private:
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Fine>());
  return 0;
}
