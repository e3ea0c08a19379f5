#include <memory>

#include "helpers_demo/battery_monitor.hpp"
#include "helpers_demo/cmd_vel_publisher.hpp"

namespace helpers_demo
{

class Controller : public rclcpp::Node
{
public:
  Controller()
  : Node("controller"), battery_(this)
  {
  }

  void init()
  {
    cmd_vel_ = std::make_shared<CmdVelPublisher>(shared_from_this(), "cmd_vel");
    battery_.start();
  }

private:
  BatteryMonitor battery_;
  std::shared_ptr<CmdVelPublisher> cmd_vel_;
};

}  // namespace helpers_demo

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto controller = std::make_shared<helpers_demo::Controller>();
  controller->init();
  rclcpp::spin(controller);
  rclcpp::shutdown();
  return 0;
}
