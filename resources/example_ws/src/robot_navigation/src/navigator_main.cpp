#include <memory>

#include "robot_navigation/navigator.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto navigator = std::make_shared<robot_navigation::Navigator>();
  rclcpp::spin(navigator->get_node_base_interface());
  rclcpp::shutdown();
  return 0;
}
