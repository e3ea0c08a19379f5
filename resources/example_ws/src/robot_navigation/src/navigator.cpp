#include "robot_navigation/navigator.hpp"

namespace robot_navigation
{

Navigator::Navigator(const rclcpp::NodeOptions & options)
: rclcpp_lifecycle::LifecycleNode("navigator", options)
{
  declare_parameter("max_speed", 0.8);
}

Navigator::CallbackReturn Navigator::on_configure(const rclcpp_lifecycle::State &)
{
  safety_ = std::make_unique<SafetyMonitor>(this);
  cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel", 10);
  scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
    "scan_filtered", 10,
    [this](const sensor_msgs::msg::LaserScan::SharedPtr msg) {on_scan(msg);});
  mode_client_ = create_client<robot_interfaces::srv::SetMode>("set_mode");
  navigate_server_ = rclcpp_action::create_server<Navigate>(
    this, "navigate",
    std::bind(&Navigator::handle_goal, this, std::placeholders::_1, std::placeholders::_2),
    std::bind(&Navigator::handle_cancel, this, std::placeholders::_1),
    std::bind(&Navigator::handle_accepted, this, std::placeholders::_1));
  return CallbackReturn::SUCCESS;
}

Navigator::CallbackReturn Navigator::on_activate(const rclcpp_lifecycle::State &)
{
  cmd_pub_->on_activate();
  return CallbackReturn::SUCCESS;
}

rclcpp_action::GoalResponse Navigator::handle_goal(
  const rclcpp_action::GoalUUID &, std::shared_ptr<const Navigate::Goal>)
{
  return safety_->stopped() ? rclcpp_action::GoalResponse::REJECT :
         rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
}

rclcpp_action::CancelResponse Navigator::handle_cancel(const std::shared_ptr<GoalHandle>)
{
  return rclcpp_action::CancelResponse::ACCEPT;
}

void Navigator::handle_accepted(const std::shared_ptr<GoalHandle> goal_handle)
{
  auto result = std::make_shared<Navigate::Result>();
  result->reached = true;
  goal_handle->succeed(result);
}

void Navigator::on_scan(const sensor_msgs::msg::LaserScan::SharedPtr)
{
}

}  // namespace robot_navigation
