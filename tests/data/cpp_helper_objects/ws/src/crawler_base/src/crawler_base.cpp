#include "crawler_base/crawler_base.hpp"

namespace crawler
{
CrawlerBase::CrawlerBase()
: Node("crawler_base")
{
  handle_ = std::shared_ptr<::rclcpp::Node>(this, [](::rclcpp::Node *) {});
  add_sensors();
  add_devices();
  drive_ = std::make_unique<VelocityInput>(
    handle_, "cmd_vel",
    std::bind(&CrawlerBase::on_twist, this, std::placeholders::_1));
}

void CrawlerBase::add_sensors()
{
  sensors_.push_back(new sensors::ImuSensor(handle_, "imu", "imu_link"));
  sensors_.push_back(
    new sensors::BatterySensor(
      handle_,
      "battery_state"));
}

void CrawlerBase::add_devices()
{
  devices_["head_lamp"] = new devices::Lamp(handle_, "head_lamp/switch");
}

void CrawlerBase::on_twist(geometry_msgs::msg::Twist::SharedPtr) {}
}  // namespace crawler
