#include "line_nodes/stages.hpp"

// The whole filter line in one process.
int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::executors::SingleThreadedExecutor executor;
  const auto stages = line_nodes::make_filter_line(rclcpp::NodeOptions());
  for (const auto & stage : stages) {
    executor.add_node(stage);
  }
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
