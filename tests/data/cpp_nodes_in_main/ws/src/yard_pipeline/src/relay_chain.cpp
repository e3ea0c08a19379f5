#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "yard_pipeline/relay_stage.hpp"
#include "yard_pipeline/stages.hpp"

// Two relays in a row and a display, each told its topics (and some their names) here.
int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::executors::MultiThreadedExecutor executor;
  auto first = std::make_shared<yard_pipeline::RelayStage>("frames", "marked_copy", "first_relay");
  auto second = std::make_shared<yard_pipeline::RelayStage>("marked_copy", "marked_frames");
  auto display = std::make_shared<yard_pipeline::DisplayStage>(
    rclcpp::NodeOptions().arguments({"--ros-args", "-r", "__node:=chain_display"}));
  executor.add_node(first);
  executor.add_node(second);
  executor.add_node(display);
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
