#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/trigger.hpp"

// A node that names itself and serves a Trigger under the name it is given.
class EchoServer : public rclcpp::Node
{
public:
  explicit EchoServer(const std::string & service_name)
  : rclcpp::Node("echo_server")
  {
    service_ = create_service<std_srvs::srv::Trigger>(
      service_name,
      [](const std::shared_ptr<std_srvs::srv::Trigger::Request>,
      std::shared_ptr<std_srvs::srv::Trigger::Response> response) {response->success = true;});
  }

private:
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr service_;
};

// The echo of the dock: the string it hands its base is the service's name, not the node's.
class DockEcho : public EchoServer
{
public:
  DockEcho()
  : EchoServer("dock/echo")
  {
  }
};

int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<DockEcho>());
  rclcpp::shutdown();
  return 0;
}
