#ifndef DEMO_CPP__TALKER_HPP_
#define DEMO_CPP__TALKER_HPP_

#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
#include "demo_cpp/visibility_control.h"

namespace demo_cpp
{

// A composable talker: declared here, defined out of line in src/talker.cpp.
class Talker : public rclcpp::Node
{
public:
  using Msg = std_msgs::msg::String;

  DEMO_CPP_PUBLIC
  explicit Talker(const rclcpp::NodeOptions & options);

private:
  void on_timer();
  void on_reset(const std_msgs::msg::Empty::SharedPtr msg);

  rclcpp::Publisher<Msg>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::Empty>::SharedPtr reset_sub_;
  rclcpp::TimerBase::SharedPtr timer_;
  size_t count_ = 0;
};

}  // namespace demo_cpp

#endif  // DEMO_CPP__TALKER_HPP_
