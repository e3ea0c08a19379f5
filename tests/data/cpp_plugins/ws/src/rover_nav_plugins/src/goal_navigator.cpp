#include <geometry_msgs/msg/pose_stamped.hpp>
#include <nav2_msgs/action/navigate_to_pose.hpp>
#include <pluginlib/class_list_macros.hpp>
#include "rover_nav_core/navigator.hpp"

namespace rover_nav_plugins
{
class GoalNavigator : public rover_nav_core::TreeNavigator<nav2_msgs::action::NavigateToPose>
{
public:
  std::string getName() override {return std::string("drive_to_goal");}

protected:
  bool configure(rclcpp_lifecycle::LifecycleNode::WeakPtr parent) override
  {
    auto node = parent.lock();
    goal_sub_ = node->create_subscription<geometry_msgs::msg::PoseStamped>(
      "goal_pose", 10,
      std::bind(&GoalNavigator::on_goal, this, std::placeholders::_1));
    return true;
  }

private:
  void on_goal(const geometry_msgs::msg::PoseStamped::SharedPtr) {}
  rclcpp::Subscription<geometry_msgs::msg::PoseStamped>::SharedPtr goal_sub_;
};
}  // namespace rover_nav_plugins

PLUGINLIB_EXPORT_CLASS(rover_nav_plugins::GoalNavigator, rover_nav_core::NavigatorBase)
