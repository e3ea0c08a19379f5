#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/twist.hpp>

class Driver : public rclcpp::Node
{
public:
  Driver()
  : Node("driver")
  {
    cmd_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel", 10);
  }

private:
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr cmd_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Driver>());
  return 0;
}
