// Sweeps lanes across a room; scored by the critics its parameters name.
#include <pluginlib/class_list_macros.hpp>

#include "floor_control/params_handler.hpp"

namespace floor_control
{
// Lays out the lanes; configured with the controller's name.
class SweepPlanner
{
public:
  void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, const std::string & name,
    ParamsHandler * handler)
  {
    parent_ = parent;
    name_ = name;
    auto getParam = handler->getParamGetter(name_);
    getParam(lane_width_, "lane_width", 0.45);
    getParam(overlap_, "overlap", 0.05f);
  }

private:
  rclcpp_lifecycle::LifecycleNode::WeakPtr parent_;
  std::string name_;
  double lane_width_{0.0};
  float overlap_{0.0f};
};

class FloorController
{
public:
  virtual ~FloorController() = default;
  virtual void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name) = 0;
};

class Sweeper : public FloorController
{
public:
  void configure(const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name)
  override
  {
    parent_ = parent;
    name_ = name;
    handler_ = std::make_unique<ParamsHandler>(parent);
    handler_->start();
    auto getParam = handler_->getParamGetter(name_);
    getParam(max_speed_, "max_speed", 0.3);
    getParam(critic_names_, "critics", std::vector<std::string>{});
    auto getServerParam = handler_->getParamGetter("");
    getServerParam(control_rate_, "control_rate", 10);
    planner_.configure(parent_, name_, handler_.get());
  }

private:
  rclcpp_lifecycle::LifecycleNode::WeakPtr parent_;
  std::string name_;
  std::unique_ptr<ParamsHandler> handler_;
  SweepPlanner planner_;
  double max_speed_{0.0};
  int control_rate_{0};
  std::vector<std::string> critic_names_;
};
}  // namespace floor_control

PLUGINLIB_EXPORT_CLASS(floor_control::Sweeper, floor_control::FloorController)
