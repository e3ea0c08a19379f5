#include "demo_cpp/talker.hpp"

#include <chrono>

#include "rclcpp_components/register_node_macro.hpp"
#include "std_msgs/msg/empty.hpp"

using namespace std::chrono_literals;
using std::placeholders::_1;

namespace demo_cpp
{

Talker::Talker(const rclcpp::NodeOptions & options)
: Node("talker", options)
{
  pub_ = this->create_publisher<Msg>("chatter", 10);
  reset_sub_ = create_subscription<std_msgs::msg::Empty>(
    "reset", rclcpp::QoS(1), std::bind(&Talker::on_reset, this, _1));
  timer_ = create_wall_timer(1s, std::bind(&Talker::on_timer, this));
}

void Talker::on_timer()
{
  Msg msg;
  msg.data = "hello " + std::to_string(count_++);
  pub_->publish(msg);
}

void Talker::on_reset(const std_msgs::msg::Empty::SharedPtr)
{
  count_ = 0;
}

}  // namespace demo_cpp

RCLCPP_COMPONENTS_REGISTER_NODE(demo_cpp::Talker)
