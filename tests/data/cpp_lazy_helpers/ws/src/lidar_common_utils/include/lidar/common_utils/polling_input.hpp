#pragma once

#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>

namespace lidar::common_utils
{
// A subscription that is read when needed instead of calling back.
template<typename MessageT>
class PollingInput
{
public:
  using SharedPtr = std::shared_ptr<PollingInput<MessageT>>;

  PollingInput(rclcpp::Node * node, const std::string & topic)
  {
    subscription_ = node->create_subscription<MessageT>(
      topic, rclcpp::QoS{1}, [](typename MessageT::ConstSharedPtr) {});
  }

  static SharedPtr create_subscription(rclcpp::Node * node, const std::string & topic)
  {
    return std::make_shared<PollingInput<MessageT>>(node, topic);
  }

private:
  typename rclcpp::Subscription<MessageT>::SharedPtr subscription_;
};
}  // namespace lidar::common_utils
