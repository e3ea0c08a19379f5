#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <rclcpp/rclcpp.hpp>
#include "crawler_base/devices/lamp.hpp"
#include "crawler_base/sensors/battery_sensor.hpp"
#include "crawler_base/sensors/imu_sensor.hpp"
#include "crawler_base/velocity_input.hpp"

namespace crawler
{
class CrawlerBase : public rclcpp::Node
{
public:
  CrawlerBase();

private:
  void add_sensors();
  void add_devices();
  void on_twist(geometry_msgs::msg::Twist::SharedPtr msg);

  // A handle on this very node, for the helpers (it must not delete the node).
  rclcpp::Node::SharedPtr handle_;
  std::vector<sensors::SensorBase *> sensors_;
  std::map<std::string, devices::Lamp *> devices_;
  std::unique_ptr<VelocityInput> drive_;
};
}  // namespace crawler
