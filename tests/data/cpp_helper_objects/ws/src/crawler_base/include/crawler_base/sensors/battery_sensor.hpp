#pragma once

#include <string>
#include <sensor_msgs/msg/battery_state.hpp>
#include "crawler_base/sensors/sensor_base.hpp"

namespace crawler
{
namespace sensors
{
// Header-only: publishes through the handle its base keeps.
class BatterySensor : public SensorBase
{
public:
  BatterySensor(std::shared_ptr<rclcpp::Node> & nh, const std::string & topic)
  : SensorBase(nh)
  {
    pub_ = nh_->create_publisher<sensor_msgs::msg::BatteryState>(topic, 10);
  }
  void publish() override {pub_->publish(sensor_msgs::msg::BatteryState());}

private:
  rclcpp::Publisher<sensor_msgs::msg::BatteryState>::SharedPtr pub_;
};
}  // namespace sensors
}  // namespace crawler
