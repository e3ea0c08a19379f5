#pragma once

#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_action/rclcpp_action.hpp>

namespace gap_driver
{
// A template helper that builds a default goal as `typename ActionT::Goal()`.
template<class ActionT>
class GoalClient
{
public:
  GoalClient(rclcpp::Node * node, const std::string & action)
  {
    client_ = rclcpp_action::create_client<ActionT>(node, action);
    goal_ = typename ActionT::Goal();
  }

private:
  typename rclcpp_action::Client<ActionT>::SharedPtr client_;
  typename ActionT::Goal goal_;
};
}  // namespace gap_driver
