#pragma once

#include <memory>
#include <string>
#include <rclcpp_action/rclcpp_action.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

namespace rover_nav_core
{
// Serves one action on the node it is given, under the name it is given, once activated.
template<class ActionT>
class ActionHost
{
public:
  ActionHost(rclcpp_lifecycle::LifecycleNode::SharedPtr node, const std::string & action_name)
  : node_(node), action_name_(action_name) {}

  void activate()
  {
    server_ = rclcpp_action::create_server<ActionT>(
      node_, action_name_,
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const typename ActionT::Goal>) {
        return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
      },
      [](const std::shared_ptr<rclcpp_action::ServerGoalHandle<ActionT>>) {
        return rclcpp_action::CancelResponse::ACCEPT;
      },
      [](const std::shared_ptr<rclcpp_action::ServerGoalHandle<ActionT>>) {});
  }

private:
  rclcpp_lifecycle::LifecycleNode::SharedPtr node_;
  std::string action_name_;
  typename rclcpp_action::Server<ActionT>::SharedPtr server_;
};
}  // namespace rover_nav_core
