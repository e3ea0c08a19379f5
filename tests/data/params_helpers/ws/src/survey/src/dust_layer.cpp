// A grid layer that marks dusty cells; its base declares each parameter under the layer's name.
#include <nav2_util/node_utils.hpp>
#include <pluginlib/class_list_macros.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

namespace survey
{
class GridLayer
{
public:
  virtual ~GridLayer() = default;

  void initialize(const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, const std::string & name)
  {
    node_ = parent;
    name_ = name;
    onInitialize();
  }

protected:
  virtual void onInitialize() = 0;

  // Declares `param_name` under the name this layer is loaded by.
  void declareParameter(const std::string & param_name, const rclcpp::ParameterValue & value)
  {
    auto node = node_.lock();
    nav2_util::declare_parameter_if_not_declared(node, name_ + "." + param_name, value);
  }

  rclcpp_lifecycle::LifecycleNode::WeakPtr node_;
  std::string name_;
};

class DustLayer : public GridLayer
{
protected:
  void onInitialize() override
  {
    declareParameter("enabled", rclcpp::ParameterValue(true));
    declareParameter("dust_threshold", rclcpp::ParameterValue(0.4));
  }
};
}  // namespace survey

PLUGINLIB_EXPORT_CLASS(survey::DustLayer, survey::GridLayer)
