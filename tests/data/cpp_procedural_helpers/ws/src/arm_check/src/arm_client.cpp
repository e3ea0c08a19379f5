#include "arm_check/arm_client.hpp"

namespace arm_check
{

ArmClient::ArmClient(const rclcpp::Node::SharedPtr & node, const std::string & arm)
: node_(node)
{
  home_client_ = node_->create_client<std_srvs::srv::Trigger>(arm + "/home");
  log_pub_ = node_->create_publisher<std_msgs::msg::String>("check_log", 10);
}

bool ArmClient::home()
{
  auto request = std::make_shared<std_srvs::srv::Trigger::Request>();
  return home_client_->async_send_request(request).valid();
}

}  // namespace arm_check
