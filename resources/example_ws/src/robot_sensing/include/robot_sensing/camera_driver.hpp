#pragma once

#include <string>

#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/image.hpp>
#include <std_srvs/srv/set_bool.hpp>

namespace robot_sensing
{

using SetBool = std_srvs::srv::SetBool;

/// Publishes camera frames; optionally offers a service to toggle auto exposure.
class CameraDriver : public rclcpp::Node
{
public:
  CameraDriver();

private:
  void grab_frame();
  void handle_auto_exposure(
    const std::shared_ptr<SetBool::Request> request,
    std::shared_ptr<SetBool::Response> response);

  std::string image_topic_ = "camera/image_raw";
  bool auto_exposure_ = true;
  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr image_pub_;
  rclcpp::Service<SetBool>::SharedPtr exposure_srv_;
  rclcpp::TimerBase::SharedPtr timer_;
};

}  // namespace robot_sensing
