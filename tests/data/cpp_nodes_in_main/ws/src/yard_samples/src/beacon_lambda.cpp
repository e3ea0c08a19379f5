#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

// The beacon written with a lambda for its timer.
class Beacon : public rclcpp::Node
{
public:
  Beacon()
  : Node("beacon")
  {
    pub_ = create_publisher<std_msgs::msg::String>("beacon", 10);
    timer_ = create_wall_timer(1s, [this]() {pub_->publish(std_msgs::msg::String());});
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Beacon>());
  rclcpp::shutdown();
  return 0;
}
