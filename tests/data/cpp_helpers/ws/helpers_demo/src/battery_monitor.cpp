#include "helpers_demo/battery_monitor.hpp"

#include "nav2_util/node_utils.hpp"

namespace helpers_demo
{

void BatteryMonitor::start()
{
  nav2_util::declare_parameter_if_not_declared(
    node_, "battery_topic", rclcpp::ParameterValue("battery_state"));
  node_->get_parameter("battery_topic", topic_);
  sub_ = node_->create_subscription<sensor_msgs::msg::BatteryState>(
    topic_, rclcpp::SensorDataQoS(),
    std::bind(&BatteryMonitor::on_battery, this, std::placeholders::_1));
}

void BatteryMonitor::on_battery(const sensor_msgs::msg::BatteryState::SharedPtr)
{
}

}  // namespace helpers_demo
