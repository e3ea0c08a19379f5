#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

// Someone is in the middle of editing this file.
class Unfinished : public rclcpp::Node
{
public:
  Unfinished()
  : Node("unfinished")
  {
    int x = (3 + ;
    pub_ = create_publisher<std_msgs::msg::String>("draft", 10);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

class Survivor : public rclcpp::Node
{
public:
  Survivor()
  : Node("survivor")
  {
    pub_ = create_publisher<std_msgs::msg::String>("alive", 10);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Survivor>());
  return 0;
}
