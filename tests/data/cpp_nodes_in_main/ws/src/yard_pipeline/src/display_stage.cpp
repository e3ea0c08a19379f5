#include "yard_pipeline/stages.hpp"

namespace yard_pipeline
{

DisplayStage::DisplayStage(const rclcpp::NodeOptions & options)
: Node("display", options)
{
  in_ = create_subscription<sensor_msgs::msg::Image>(
    "marked_frames", 5, [](sensor_msgs::msg::Image::UniquePtr) {});
}

}  // namespace yard_pipeline
