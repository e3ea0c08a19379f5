#ifndef HELPERS_DEMO__SIMPLE_ACTION_SERVER_HPP_
#define HELPERS_DEMO__SIMPLE_ACTION_SERVER_HPP_

#include <functional>
#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"

namespace helpers_demo
{

// A generic wrapper: the action type is the template argument of each instantiation.
template<typename ActionT, typename NodeT = rclcpp::Node::SharedPtr>
class SimpleActionServer
{
public:
  using ExecuteCallback = std::function<void ()>;

  SimpleActionServer(NodeT node, const std::string & action_name, ExecuteCallback execute)
  : action_name_(action_name), execute_(execute)
  {
    server_ = rclcpp_action::create_server<ActionT>(
      node->get_node_base_interface(), node->get_node_clock_interface(),
      node->get_node_logging_interface(), node->get_node_waitables_interface(),
      action_name_,
      std::bind(&SimpleActionServer::handle_goal, this, std::placeholders::_1, std::placeholders::_2),
      std::bind(&SimpleActionServer::handle_cancel, this, std::placeholders::_1),
      std::bind(&SimpleActionServer::handle_accepted, this, std::placeholders::_1));
  }

private:
  rclcpp_action::GoalResponse handle_goal(
    const rclcpp_action::GoalUUID &, std::shared_ptr<const typename ActionT::Goal>)
  {
    return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
  }
  rclcpp_action::CancelResponse handle_cancel(
    const std::shared_ptr<rclcpp_action::ServerGoalHandle<ActionT>>)
  {
    return rclcpp_action::CancelResponse::ACCEPT;
  }
  void handle_accepted(const std::shared_ptr<rclcpp_action::ServerGoalHandle<ActionT>>)
  {
    execute_();
  }

  std::string action_name_;
  ExecuteCallback execute_;
  typename rclcpp_action::Server<ActionT>::SharedPtr server_;
};

}  // namespace helpers_demo

#endif  // HELPERS_DEMO__SIMPLE_ACTION_SERVER_HPP_
