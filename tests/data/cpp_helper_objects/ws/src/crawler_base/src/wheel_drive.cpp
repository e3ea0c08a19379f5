#include <memory>
#include "crawler_base/wheel_odometry.hpp"

namespace crawler
{
class WheelDrive : public rclcpp::Node
{
public:
  explicit WheelDrive(double wheel_radius)
  : Node("wheel_drive")
  {
    nh_ = std::shared_ptr<::rclcpp::Node>(this, [](::rclcpp::Node *) {});
    odometry_ = std::make_unique<WheelOdometry>(nh_, wheel_radius);
  }

private:
  std::shared_ptr<rclcpp::Node> nh_;
  std::unique_ptr<WheelOdometry> odometry_;
};
}  // namespace crawler

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<crawler::WheelDrive>(0.033));
  rclcpp::shutdown();
  return 0;
}
