#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/header.hpp"
#include "std_srvs/srv/trigger.hpp"

// A machine of the yard: answers pings and sends a heartbeat under its own name.
class Worker : public rclcpp::Node
{
public:
  Worker()
  : Node("worker")
  {
    beat_pub_ = create_publisher<std_msgs::msg::Header>("~/heartbeat", 10);
    ping_srv_ = create_service<std_srvs::srv::Trigger>(
      "~/ping",
      [](const std::shared_ptr<std_srvs::srv::Trigger::Request>,
      std::shared_ptr<std_srvs::srv::Trigger::Response> response) {response->success = true;});
  }

private:
  rclcpp::Publisher<std_msgs::msg::Header>::SharedPtr beat_pub_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr ping_srv_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Worker>());
  rclcpp::shutdown();
  return 0;
}
