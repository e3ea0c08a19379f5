#pragma once

#include <functional>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_srvs/srv/set_bool.hpp>

namespace crawler
{
namespace devices
{
// A device answers a service on the node it is handed.
class Lamp
{
public:
  Lamp(std::shared_ptr<rclcpp::Node> & nh, const std::string & service)
  {
    srv_ = nh->create_service<std_srvs::srv::SetBool>(
      service,
      std::bind(&Lamp::on_switch, this, std::placeholders::_1, std::placeholders::_2));
  }

private:
  void on_switch(
    const std::shared_ptr<std_srvs::srv::SetBool::Request>,
    std::shared_ptr<std_srvs::srv::SetBool::Response> response) {response->success = true;}
  rclcpp::Service<std_srvs::srv::SetBool>::SharedPtr srv_;
};
}  // namespace devices
}  // namespace crawler
