#include <string>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "yard_pipeline/relay_stage.hpp"

namespace yard_pipeline
{

RelayStage::RelayStage(
  const std::string & input, const std::string & output, const std::string & node_name)
: Node(node_name)
{
  out_ = create_publisher<sensor_msgs::msg::Image>(output, 5);
  in_ = create_subscription<sensor_msgs::msg::Image>(
    input, 5, [this](sensor_msgs::msg::Image::UniquePtr msg) {out_->publish(std::move(msg));});
}

}  // namespace yard_pipeline
