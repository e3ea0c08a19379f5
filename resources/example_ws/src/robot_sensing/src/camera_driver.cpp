#include "robot_sensing/camera_driver.hpp"

#include <chrono>

using namespace std::chrono_literals;

namespace robot_sensing
{

CameraDriver::CameraDriver()
: Node("camera_driver")
{
  const bool use_exposure_service = declare_parameter("use_exposure_service", false);

  image_pub_ = create_publisher<sensor_msgs::msg::Image>(image_topic_, rclcpp::SensorDataQoS());
  if (use_exposure_service) {
    exposure_srv_ = create_service<SetBool>(
      "camera/set_auto_exposure",
      std::bind(
        &CameraDriver::handle_auto_exposure, this,
        std::placeholders::_1, std::placeholders::_2));
  }
  timer_ = create_wall_timer(33ms, std::bind(&CameraDriver::grab_frame, this));
}

void CameraDriver::grab_frame()
{
  sensor_msgs::msg::Image frame;
  frame.header.stamp = now();
  frame.encoding = "rgb8";
  image_pub_->publish(frame);
}

void CameraDriver::handle_auto_exposure(
  const std::shared_ptr<SetBool::Request> request,
  std::shared_ptr<SetBool::Response> response)
{
  auto_exposure_ = request->data;
  response->success = true;
}

}  // namespace robot_sensing
