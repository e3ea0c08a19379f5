#include <array>

#include "line_nodes/stages.hpp"

// One watcher per zone of the yard, all in one process.
int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::executors::MultiThreadedExecutor executor;
  const std::array<std::string, 2> zones{"dock", "gate"};
  std::vector<std::shared_ptr<line_nodes::ZoneWatcher>> watchers;
  for (const auto & zone : zones) {
    watchers.push_back(std::make_shared<line_nodes::ZoneWatcher>(zone));
    executor.add_node(watchers.back());
  }
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
