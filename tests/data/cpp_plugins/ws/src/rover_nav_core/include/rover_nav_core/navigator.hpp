#pragma once

#include <memory>
#include <string>
#include "rover_nav_core/action_host.hpp"

namespace rover_nav_core
{
class NavigatorBase
{
public:
  virtual ~NavigatorBase() = default;
  virtual bool on_configure(rclcpp_lifecycle::LifecycleNode::WeakPtr parent) = 0;
};

// Every navigator serves the action it is named after; the derived class gives the name.
template<class ActionT>
class TreeNavigator : public NavigatorBase
{
public:
  bool on_configure(rclcpp_lifecycle::LifecycleNode::WeakPtr parent) final
  {
    auto node = parent.lock();
    host_ = std::make_unique<ActionHost<ActionT>>(node, getName());
    return configure(parent);
  }

  virtual std::string getName() = 0;

protected:
  virtual bool configure(rclcpp_lifecycle::LifecycleNode::WeakPtr parent) = 0;
  std::unique_ptr<ActionHost<ActionT>> host_;
};
}  // namespace rover_nav_core
