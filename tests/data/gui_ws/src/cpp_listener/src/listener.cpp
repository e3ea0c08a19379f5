#include <functional>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
#include "std_srvs/srv/trigger.hpp"

namespace cpp_listener
{

class Listener : public rclcpp::Node
{
public:
  Listener()
  : Node("listener")
  {
    subscription_ = create_subscription<std_msgs::msg::String>(
      "chatter", 10, std::bind(&Listener::on_message, this, std::placeholders::_1));
    service_ = create_service<std_srvs::srv::Trigger>(
      "reset", std::bind(&Listener::on_reset, this, std::placeholders::_1, std::placeholders::_2));
  }

private:
  void on_message(const std_msgs::msg::String & msg)
  {
    RCLCPP_INFO(get_logger(), "heard %s", msg.data.c_str());
    ++count_;
  }

  void on_reset(
    const std::shared_ptr<std_srvs::srv::Trigger::Request>,
    std::shared_ptr<std_srvs::srv::Trigger::Response> response)
  {
    count_ = 0;
    response->success = true;
  }

  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr subscription_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr service_;
  int count_ = 0;
};

}  // namespace cpp_listener

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<cpp_listener::Listener>());
  rclcpp::shutdown();
  return 0;
}
