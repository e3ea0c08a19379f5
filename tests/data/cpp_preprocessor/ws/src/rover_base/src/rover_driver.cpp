// The rover's drive node. The two command paths below open their braces differently in
// each branch; only one of them is compiled, so the class is well formed after #if.
#include <functional>
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rover_base/topics.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "sensor_msgs/msg/range.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/string.hpp"

#define DRIVER_CLAMP_SPEED 1

class RoverDriver : public rclcpp::Node
{
public:
  RoverDriver()
  : Node("rover_driver")
  {
    odom_pub_ = create_publisher<nav_msgs::msg::Odometry>(ROVER_ODOM_TOPIC, 10);
#if DRIVER_CLAMP_SPEED
    cmd_sub_ = create_subscription<geometry_msgs::msg::Twist>(
      ROVER_CMD_TOPIC, 10, [this](geometry_msgs::msg::Twist::SharedPtr msg) {
        if (msg->linear.x > 1.0) {
          msg->linear.x = 1.0;
#else
    cmd_sub_ = create_subscription<geometry_msgs::msg::Twist>(
      ROVER_CMD_TOPIC, 10, [this](geometry_msgs::msg::Twist::SharedPtr msg) {
        {
#endif
          drive(*msg);
        }
      });
#ifdef ROVER_WITH_LIDAR
    scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
      "scan", rclcpp::SensorDataQoS(),
      std::bind(&RoverDriver::on_scan, this, std::placeholders::_1));
#else
    sonar_sub_ = create_subscription<sensor_msgs::msg::Range>(
      "sonar", 10, std::bind(&RoverDriver::on_sonar, this, std::placeholders::_1));
#endif
#if RCLCPP_VERSION_GTE(28, 0, 0)
    stop_pub_ = create_publisher<std_msgs::msg::Bool>("emergency_stop", rclcpp::QoS(1).reliable());
#else
    stop_pub_ = create_publisher<std_msgs::msg::Bool>("estop", 1);
#endif
#if 0
    debug_pub_ = create_publisher<std_msgs::msg::String>("driver_debug", 10;
#endif
  }

private:
  void drive(const geometry_msgs::msg::Twist &) {}
  void on_scan(sensor_msgs::msg::LaserScan::SharedPtr) {}
#ifndef ROVER_WITH_LIDAR
  void on_sonar(sensor_msgs::msg::Range::SharedPtr) {}
#endif

  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr odom_pub_;
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr stop_pub_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr cmd_sub_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr scan_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<RoverDriver>());
  rclcpp::shutdown();
  return 0;
}
