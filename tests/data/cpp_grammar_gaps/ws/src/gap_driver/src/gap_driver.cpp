#include <memory>
#include <string>
#include <vector>

#include <nav2_msgs/action/navigate_to_pose.hpp>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>
#include <std_msgs/msg/float64.hpp>
#include "gap_driver/goal_client.hpp"

namespace gap_driver
{
class GapDriver : public rclcpp::Node
{
public:
  GapDriver()
  : Node("gap_driver")
  {
    scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
      "scan", rclcpp::SensorDataQoS(),
      std::bind(&GapDriver::on_scan, this, std::placeholders::_1));
    goals_ = std::make_unique<GoalClient<nav2_msgs::action::NavigateToPose>>(
      this, "navigate_to_pose");
    allocate(64);
  }

  // A half-written member: the one declaration that is lost.
  void unfinished() { int width = ; measure(}; }

  void start_reporting(const std::vector<double> & weights = {})
  {
    weights_ = weights;
    gap_pub_ = create_publisher<std_msgs::msg::Float64>("widest_gap", 10);
  }

private:
  // An array of row pointers, value-initialised: `new double *[rows]()`.
  void allocate(int rows)
  {
    rows_ = new double *[rows]();
  }

  void on_scan(const sensor_msgs::msg::LaserScan::SharedPtr) {}

  double ** rows_{nullptr};
  std::vector<double> weights_;
  std::unique_ptr<GoalClient<nav2_msgs::action::NavigateToPose>> goals_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr scan_sub_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr gap_pub_;
};
}  // namespace gap_driver

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<gap_driver::GapDriver>());
  rclcpp::shutdown();
  return 0;
}
