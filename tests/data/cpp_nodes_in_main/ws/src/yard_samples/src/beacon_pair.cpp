#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "yard_samples/beacon.hpp"

using yard_samples::Beacon;

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::executors::SingleThreadedExecutor exec;
  auto north = std::make_shared<Beacon>("north_beacon", "north");
  auto south = std::make_shared<Beacon>("south_beacon", "south");
  exec.add_node(north);
  exec.add_node(south);
  exec.spin();
  rclcpp::shutdown();
  return 0;
}
