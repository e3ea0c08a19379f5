#pragma once

#include <memory>
#include <rclcpp/rclcpp.hpp>

namespace crawler
{
namespace sensors
{
// Every sensor keeps the node handle it is given and publishes on it.
class SensorBase
{
public:
  explicit SensorBase(std::shared_ptr<rclcpp::Node> & nh) : nh_(nh) {}
  virtual ~SensorBase() = default;
  virtual void publish() = 0;

protected:
  std::shared_ptr<rclcpp::Node> nh_;
};
}  // namespace sensors
}  // namespace crawler
