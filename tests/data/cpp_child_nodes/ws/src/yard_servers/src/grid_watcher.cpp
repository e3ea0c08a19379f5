#include <nav_msgs/msg/occupancy_grid.hpp>
#include <rclcpp/rclcpp.hpp>

// Reads both servers' grid maps by their names relative to the robot's namespace.
class GridWatcher : public rclcpp::Node
{
public:
  GridWatcher()
  : Node("grid_watcher")
  {
    world_sub_ = create_subscription<nav_msgs::msg::OccupancyGrid>(
      "world_grid/grid", 1, [](nav_msgs::msg::OccupancyGrid::ConstSharedPtr) {});
    near_sub_ = create_subscription<nav_msgs::msg::OccupancyGrid>(
      "near_grid/grid", 1, [](nav_msgs::msg::OccupancyGrid::ConstSharedPtr) {});
  }

private:
  rclcpp::Subscription<nav_msgs::msg::OccupancyGrid>::SharedPtr world_sub_;
  rclcpp::Subscription<nav_msgs::msg::OccupancyGrid>::SharedPtr near_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<GridWatcher>());
  rclcpp::shutdown();
  return 0;
}
