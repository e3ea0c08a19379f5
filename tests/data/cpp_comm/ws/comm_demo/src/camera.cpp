#include <memory>

#include "image_transport/image_transport.hpp"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/camera_info.hpp"

// image_transport publishers carry sensor_msgs/msg/Image.
class Camera : public rclcpp::Node
{
public:
  Camera()
  : Node("camera")
  {
    image_pub_ = image_transport::create_publisher(this, "image_raw");
    info_pub_ = create_publisher<sensor_msgs::msg::CameraInfo>("camera_info", 10);
  }

  void start()
  {
    image_transport::ImageTransport it(shared_from_this());
    preview_pub_ = it.advertise("preview", 1);
  }

private:
  image_transport::Publisher image_pub_;
  image_transport::Publisher preview_pub_;
  rclcpp::Publisher<sensor_msgs::msg::CameraInfo>::SharedPtr info_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto camera = std::make_shared<Camera>();
  camera->start();
  rclcpp::spin(camera);
  rclcpp::shutdown();
  return 0;
}
