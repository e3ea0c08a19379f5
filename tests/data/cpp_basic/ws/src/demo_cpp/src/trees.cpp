#include <memory>
#include <string>

#include "behaviortree_cpp/action_node.h"
#include "rclcpp/rclcpp.hpp"

// Behaviour-tree classes are called "*Node" but are not ROS nodes.
class SpinActionNode : public BT::SyncActionNode
{
public:
  SpinActionNode(const std::string & name, const BT::NodeConfig & config)
  : BT::SyncActionNode(name, config) {}

  BT::NodeStatus tick() override {return BT::NodeStatus::SUCCESS;}
};

class TreeNode
{
public:
  std::string name;
};

// `Node` without `using rclcpp::Node` is some other Node.
class GraphNode : public Node
{
};

int main()
{
  auto tree = std::make_shared<TreeNode>();
  return tree->name.empty() ? 0 : 1;
}
