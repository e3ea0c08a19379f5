#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <rclcpp/rclcpp.hpp>

namespace lidar::common_utils
{
// Publishes debug values under a prefix; a topic's publisher is made the first time a value
// is published under its name.
class DebugChannel
{
public:
  DebugChannel(rclcpp::Node * node, const char * prefix) : node_(node), prefix_(prefix) {}

  template<class MessageT>
  void publish(const std::string & name, const MessageT & message)
  {
    if (publishers_.count(name) == 0) {
      publishers_[name] = node_->create_publisher<MessageT>(std::string(prefix_) + "/" + name, 1);
    }
    std::static_pointer_cast<rclcpp::Publisher<MessageT>>(publishers_.at(name))->publish(message);
  }

private:
  rclcpp::Node * node_;
  const char * prefix_;
  std::unordered_map<std::string, std::shared_ptr<rclcpp::PublisherBase>> publishers_;
};
}  // namespace lidar::common_utils
