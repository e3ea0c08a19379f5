#include "line_nodes/stages.hpp"

#include "sensor_msgs/msg/laser_scan.hpp"
#include "std_msgs/msg/bool.hpp"

namespace line_nodes
{

std::vector<rclcpp::Node::SharedPtr> make_filter_line(const rclcpp::NodeOptions & options)
{
  std::vector<rclcpp::Node::SharedPtr> stages;
  stages.push_back(
    std::make_shared<PassStage<sensor_msgs::msg::LaserScan>>(
      StageSettings{
        .node_name = "scan_gate",
        .input_topic = "scan_raw",
        .output_topic = "scan_gated"},
      options));
  StageSettings counter;
  counter.node_name = "scan_counter";
  counter.input_topic = "scan_gated";
  stages.push_back(std::make_shared<CountStage<sensor_msgs::msg::LaserScan>>(counter, options));
  return stages;
}

namespace
{
std::shared_ptr<ZoneWatcher> build_far() {return std::make_shared<ZoneWatcher>("far");}
std::shared_ptr<ZoneWatcher> far_step_three() {return build_far();}
std::shared_ptr<ZoneWatcher> far_step_two() {return far_step_three();}
std::shared_ptr<ZoneWatcher> far_step_one() {return far_step_two();}
}  // namespace

std::shared_ptr<ZoneWatcher> far_watcher()
{
  return far_step_one();
}

ZoneWatcher::ZoneWatcher(const std::string & zone)
: rclcpp::Node(zone + "_watcher")
{
  occupied_ = create_subscription<std_msgs::msg::Bool>(
    zone + "/occupied", 1, [](std_msgs::msg::Bool::ConstSharedPtr) {});
}

}  // namespace line_nodes
