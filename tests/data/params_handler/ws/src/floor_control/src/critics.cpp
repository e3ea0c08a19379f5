// Critics of a cleaning path; each declares under the name the controller gives it.
#include <pluginlib/class_list_macros.hpp>

#include "floor_control/params_handler.hpp"

namespace floor_control
{
class EdgeCritic : public Critic
{
protected:
  void initialize() override
  {
    auto getParam = handler_->getParamGetter(name_);
    getParam(weight_, "weight", 2.0);
    getParam(margin_, "margin", 0.1);
  }

private:
  double weight_{0.0};
  double margin_{0.0};
};

class SpeedCritic : public Critic
{
protected:
  void initialize() override
  {
    auto getParam = handler_->getParamGetter(name_);
    getParam(weight_, "weight", 1.0);
    getParam(enabled_, "enabled", true);
  }

private:
  double weight_{0.0};
  bool enabled_{true};
};
}  // namespace floor_control

PLUGINLIB_EXPORT_CLASS(floor_control::EdgeCritic, floor_control::Critic)
PLUGINLIB_EXPORT_CLASS(floor_control::SpeedCritic, floor_control::Critic)
