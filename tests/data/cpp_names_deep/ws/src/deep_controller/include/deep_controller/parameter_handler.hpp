// The controller's parameters live in a plain struct; a handler class declares them and fills
// the struct, and the server only ever reads the struct's fields.
#pragma once

#include <memory>
#include <string>

#include "rclcpp_lifecycle/lifecycle_node.hpp"

namespace deep_controller
{

struct Parameters
{
  double frequency;
  std::string odom_topic;
  std::string speed_limit_topic;
  std::string base_frame;
  std::string cmd_topic = "cmd_vel";
};

// Declares `name` with `fallback` unless it is declared already, and returns its value.
template<typename T>
T declare_or_get_parameter(
  const rclcpp_lifecycle::LifecycleNode::SharedPtr & node, const std::string & name,
  const T & fallback)
{
  if (!node->has_parameter(name)) {
    return node->declare_parameter(name, fallback);
  }
  return node->get_parameter(name).get_value<T>();
}

// Owns the struct; derived handlers fill it.
template<typename ParamsT>
class ParameterHandlerBase
{
public:
  ParamsT * getParams() {return &params_;}

protected:
  ParamsT params_;
};

class ParameterHandler : public ParameterHandlerBase<Parameters>
{
public:
  explicit ParameterHandler(const rclcpp_lifecycle::LifecycleNode::SharedPtr & node);
};

}  // namespace deep_controller
