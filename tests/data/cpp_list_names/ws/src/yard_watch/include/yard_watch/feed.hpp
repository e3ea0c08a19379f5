#pragma once

#include <string>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "sensor_msgs/msg/range.hpp"

namespace yard_watch
{

// One sensor feed of the hub. Its topic is the parameter `<feed name>.topic`, which
// defaults to the feed's own name.
class Feed
{
public:
  Feed(rclcpp::Node * node, const std::string & feed_name)
  : node_(node), feed_name_(feed_name) {}

  void start()
  {
    std::string topic;
    readTopic(topic);
    sub_ = node_->create_subscription<sensor_msgs::msg::LaserScan>(
      topic, 10, [](sensor_msgs::msg::LaserScan::SharedPtr) {});
  }

protected:
  void readTopic(std::string & topic)
  {
    readCommon(topic);
  }

  void readCommon(std::string & topic)
  {
    topic = node_->declare_parameter(feed_name_ + ".topic", std::string("scan"));
  }

  rclcpp::Node * node_;
  std::string feed_name_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr sub_;
};

// A sonar of the hub: its ranges arrive on the topic `<feed name>.range_topic` names, which
// has no default.
class SonarFeed
{
public:
  SonarFeed(rclcpp::Node * node, const std::string & feed_name)
  {
    const std::string topic = node->declare_parameter<std::string>(feed_name + ".range_topic");
    if (!topic.empty()) {
      sub_ = node->create_subscription<sensor_msgs::msg::Range>(
        topic, 10, [](sensor_msgs::msg::Range::SharedPtr) {});
    }
  }

private:
  rclcpp::Subscription<sensor_msgs::msg::Range>::SharedPtr sub_;
};

}  // namespace yard_watch
