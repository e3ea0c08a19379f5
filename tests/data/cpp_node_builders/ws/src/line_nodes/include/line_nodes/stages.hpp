#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rclcpp/rclcpp.hpp"

namespace line_nodes
{

// What a stage is told when it is made: its node name and the topics it joins.
struct StageSettings
{
  std::string node_name;
  std::string input_topic;
  std::string output_topic;
};

// Passes each message on unchanged, from its input topic to its output topic.
template<typename MessageT>
class PassStage : public rclcpp::Node
{
public:
  PassStage(const StageSettings & settings, const rclcpp::NodeOptions & options)
  : rclcpp::Node(settings.node_name, options)
  {
    out_ = create_publisher<MessageT>(settings.output_topic, 10);
    in_ = create_subscription<MessageT>(
      settings.input_topic, 10,
      [this](typename MessageT::ConstSharedPtr msg) {out_->publish(*msg);});
  }

private:
  typename rclcpp::Publisher<MessageT>::SharedPtr out_;
  typename rclcpp::Subscription<MessageT>::SharedPtr in_;
};

// Counts what arrives on its input topic and publishes nothing.
template<typename MessageT>
class CountStage : public rclcpp::Node
{
public:
  CountStage(const StageSettings & settings, const rclcpp::NodeOptions & options)
  : rclcpp::Node(settings.node_name, options)
  {
    in_ = create_subscription<MessageT>(
      settings.input_topic, 10, [this](typename MessageT::ConstSharedPtr) {++count_;});
  }

private:
  typename rclcpp::Subscription<MessageT>::SharedPtr in_;
  std::size_t count_ = 0;
};

// Watches one zone: hears `<zone>/occupied`.
class ZoneWatcher : public rclcpp::Node
{
public:
  explicit ZoneWatcher(const std::string & zone);

private:
  rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr occupied_;
};

// The stages of one filter line, built from their settings.
std::vector<rclcpp::Node::SharedPtr> make_filter_line(const rclcpp::NodeOptions & options);

// A watcher for the far zone, made several calls down.
std::shared_ptr<ZoneWatcher> far_watcher();

}  // namespace line_nodes
