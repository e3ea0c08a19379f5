#include <memory>

#include "helpers_demo/simple_action_server.hpp"
#include "nav2_msgs/action/dock_robot.hpp"

namespace helpers_demo
{

class Docker : public rclcpp::Node
{
public:
  using DockRobot = nav2_msgs::action::DockRobot;
  using ActionServer = SimpleActionServer<DockRobot>;

  Docker()
  : Node("docker")
  {
  }

  void activate()
  {
    server_ = std::make_unique<ActionServer>(
      shared_from_this(), "dock_robot", std::bind(&Docker::dock, this));
  }

private:
  void dock() {}

  std::unique_ptr<ActionServer> server_;
};

}  // namespace helpers_demo

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto docker = std::make_shared<helpers_demo::Docker>();
  docker->activate();
  rclcpp::spin(docker);
  rclcpp::shutdown();
  return 0;
}
