#include <memory>

#include "depot_map/depot_map.hpp"
#include "rclcpp/rclcpp.hpp"

int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::executors::SingleThreadedExecutor executor;
  auto north = std::make_shared<depot_map::DepotMap>("north_map");
  auto south = std::make_shared<depot_map::DepotMap>("south_map");
  executor.add_node(north);
  executor.add_node(south);
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
