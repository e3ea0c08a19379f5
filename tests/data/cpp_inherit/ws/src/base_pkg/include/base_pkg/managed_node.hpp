#ifndef BASE_PKG__MANAGED_NODE_HPP_
#define BASE_PKG__MANAGED_NODE_HPP_

#include <string>

#include "diagnostic_msgs/msg/diagnostic_array.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"

namespace base_pkg
{

// Project base class: every managed node reports diagnostics.
class ManagedNode : public rclcpp_lifecycle::LifecycleNode
{
public:
  explicit ManagedNode(const std::string & name)
  : rclcpp_lifecycle::LifecycleNode(name)
  {
    diagnostics_pub_ = create_publisher<diagnostic_msgs::msg::DiagnosticArray>(
      "/diagnostics", 1);
  }

protected:
  rclcpp_lifecycle::LifecyclePublisher<diagnostic_msgs::msg::DiagnosticArray>::SharedPtr
    diagnostics_pub_;
};

// A helper whose name ends in Node but that is no ROS node.
class BtActionNode
{
public:
  virtual ~BtActionNode() = default;
};

}  // namespace base_pkg

#endif  // BASE_PKG__MANAGED_NODE_HPP_
