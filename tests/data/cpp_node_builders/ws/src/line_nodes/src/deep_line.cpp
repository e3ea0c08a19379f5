#include "line_nodes/stages.hpp"

// One watcher built here, one five calls away in the library: past what is followed from main.
int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::executors::SingleThreadedExecutor executor;
  executor.add_node(std::make_shared<line_nodes::ZoneWatcher>("near"));
  executor.add_node(line_nodes::far_watcher());
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
