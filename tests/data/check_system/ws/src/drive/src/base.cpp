#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "nav_msgs/msg/occupancy_grid.hpp"
#include "rclcpp/rclcpp.hpp"

namespace drive
{

// Drives the wheels; insists on reliable velocity commands.
class Base : public rclcpp::Node
{
public:
  Base()
  : Node("base")
  {
    cmd_sub_ = create_subscription<geometry_msgs::msg::Twist>(
      "cmd_vel", rclcpp::QoS(rclcpp::KeepLast(1)).reliable(),
      std::bind(&Base::on_cmd, this, std::placeholders::_1));
    // Through a project wrapper that takes the callback before the QoS.
    map_sub_ = create_subscription<nav_msgs::msg::OccupancyGrid>(
      "map", std::bind(&Base::on_map, this, std::placeholders::_1),
      rclcpp::QoS(1).transient_local());
  }

private:
  void on_cmd(const geometry_msgs::msg::Twist &) {}
  void on_map(const nav_msgs::msg::OccupancyGrid &) {}

  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr cmd_sub_;
  rclcpp::Subscription<nav_msgs::msg::OccupancyGrid>::SharedPtr map_sub_;
};

}  // namespace drive

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<drive::Base>());
  rclcpp::shutdown();
}
