#include "yard_pipeline/stages.hpp"

namespace yard_pipeline
{

MarkerStage::MarkerStage(const rclcpp::NodeOptions & options)
: Node("marker", options)
{
  out_ = create_publisher<sensor_msgs::msg::Image>("marked_frames", 5);
  in_ = create_subscription<sensor_msgs::msg::Image>(
    "frames", 5, [this](sensor_msgs::msg::Image::UniquePtr msg) {out_->publish(std::move(msg));});
}

}  // namespace yard_pipeline
