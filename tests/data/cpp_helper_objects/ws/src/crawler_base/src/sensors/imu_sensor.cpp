#include "crawler_base/sensors/imu_sensor.hpp"

using crawler::sensors::ImuSensor;

ImuSensor::ImuSensor(
  std::shared_ptr<rclcpp::Node> & nh, const std::string & topic, const std::string & frame)
: SensorBase(nh), frame_(frame)
{
  pub_ = nh->create_publisher<sensor_msgs::msg::Imu>(topic, rclcpp::SensorDataQoS());
}

void ImuSensor::publish()
{
  sensor_msgs::msg::Imu msg;
  msg.header.frame_id = frame_;
  pub_->publish(msg);
}
