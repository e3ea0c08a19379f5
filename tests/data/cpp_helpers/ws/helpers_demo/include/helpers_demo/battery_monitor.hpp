#ifndef HELPERS_DEMO__BATTERY_MONITOR_HPP_
#define HELPERS_DEMO__BATTERY_MONITOR_HPP_

#include <string>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/battery_state.hpp"

namespace helpers_demo
{

class BatteryMonitor
{
public:
  explicit BatteryMonitor(rclcpp::Node * node)
  : node_(node) {}

  void start();

private:
  void on_battery(const sensor_msgs::msg::BatteryState::SharedPtr msg);

  rclcpp::Node * node_;
  std::string topic_;
  rclcpp::Subscription<sensor_msgs::msg::BatteryState>::SharedPtr sub_;
};

}  // namespace helpers_demo

#endif  // HELPERS_DEMO__BATTERY_MONITOR_HPP_
