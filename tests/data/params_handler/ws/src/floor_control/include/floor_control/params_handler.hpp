// Declares parameters on the node it is given, through getters bound to a namespace.
#pragma once

#include <nav2_util/node_utils.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

namespace floor_control
{
class ParamsHandler
{
public:
  explicit ParamsHandler(const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent)
  : node_(parent)
  {
    node_name_ = parent.lock()->get_name();
  }

  // Settings of the handler itself, under the node's own name.
  void start()
  {
    auto getParam = getParamGetter(node_name_);
    getParam(verbose_, "verbose", false);
  }

  auto getParamGetter(const std::string & ns)
  {
    return [this, ns](auto & setting, const std::string & name, auto default_value) {
             getParam(setting, ns.empty() ? name : ns + "." + name, default_value);
           };
  }

private:
  template<typename SettingT, typename ParamT>
  void getParam(SettingT & setting, const std::string & name, ParamT default_value)
  {
    auto node = node_.lock();
    nav2_util::declare_parameter_if_not_declared(
      node, name, rclcpp::ParameterValue(default_value));
    node->get_parameter(name, setting);
  }

  rclcpp_lifecycle::LifecycleNode::WeakPtr node_;
  std::string node_name_;
  bool verbose_{false};
};

// What a critic scores a cleaning path by.
class Critic
{
public:
  virtual ~Critic() = default;

  void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, const std::string & name,
    ParamsHandler * handler)
  {
    parent_ = parent;
    name_ = name;
    handler_ = handler;
    initialize();
  }

protected:
  virtual void initialize() = 0;

  rclcpp_lifecycle::LifecycleNode::WeakPtr parent_;
  std::string name_;
  ParamsHandler * handler_{nullptr};
};
}  // namespace floor_control
