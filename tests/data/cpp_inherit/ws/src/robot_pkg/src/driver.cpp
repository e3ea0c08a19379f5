#include "robot_pkg/driver.hpp"

using std::placeholders::_1;

namespace robot_pkg
{

Driver::Driver()
: base_pkg::ManagedNode("driver")
{
}

CallbackReturn Driver::on_configure(const rclcpp_lifecycle::State &)
{
  cmd_sub_ = create_subscription<geometry_msgs::msg::Twist>(
    "cmd_vel", 10, std::bind(&Driver::on_cmd_vel, this, _1));
  odom_pub_ = create_publisher<nav_msgs::msg::Odometry>("odom", 10);
  return CallbackReturn::SUCCESS;
}

void Driver::on_cmd_vel(const geometry_msgs::msg::Twist::SharedPtr)
{
}

SafeDriver::SafeDriver()
{
  stop_pub_ = this->create_publisher<geometry_msgs::msg::Twist>("emergency_stop", 1);
}

}  // namespace robot_pkg
