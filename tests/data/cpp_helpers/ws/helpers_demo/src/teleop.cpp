#include <memory>

#include "helpers_demo/cmd_vel_publisher.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("teleop");
  helpers_demo::CmdVelPublisher publisher(node, "teleop/cmd_vel");
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
