#include <memory>

#include "robot_sensing/camera_driver.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<robot_sensing::CameraDriver>());
  rclcpp::shutdown();
  return 0;
}
