#pragma once

#include <string>
#include <sensor_msgs/msg/imu.hpp>
#include "crawler_base/sensors/sensor_base.hpp"

namespace crawler
{
namespace sensors
{
class ImuSensor : public SensorBase
{
public:
  ImuSensor(
    std::shared_ptr<rclcpp::Node> & nh, const std::string & topic = "imu",
    const std::string & frame = "imu_link");
  void publish() override;

private:
  rclcpp::Publisher<sensor_msgs::msg::Imu>::SharedPtr pub_;
  std::string frame_;
};
}  // namespace sensors
}  // namespace crawler
