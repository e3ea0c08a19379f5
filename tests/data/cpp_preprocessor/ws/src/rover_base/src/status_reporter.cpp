// Reports the rover's wheel and battery state. The wheel count and the topic names come
// from rover_base/topics.hpp; the report period from the package's CMakeLists.txt.
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rover_base/topics.hpp"
#include "std_msgs/msg/float32.hpp"
#include "std_msgs/msg/string.hpp"

#ifndef REPORT_PERIOD_MS
#error "the build sets REPORT_PERIOD_MS"
#endif

namespace rover_base
{

class StatusReporter : public rclcpp::Node
{
public:
  StatusReporter()
  : Node("status_reporter")
  {
    status_pub_ = create_publisher<std_msgs::msg::String>(ROVER_STATUS_TOPIC, 10);
#if ROVER_WHEELS == 4
    wheel_pubs_.push_back(create_publisher<std_msgs::msg::Float32>("wheels/front", 10));
#elif ROVER_WHEELS == 6 && REPORT_PERIOD_MS < 1000
    wheel_pubs_.push_back(create_publisher<std_msgs::msg::Float32>("wheels/middle", 10));
#elif ROVER_WHEELS == 6
    wheel_pubs_.push_back(create_publisher<std_msgs::msg::Float32>("wheels/slow_middle", 10));
#else
    wheel_pubs_.push_back(create_publisher<std_msgs::msg::Float32>("wheels/unknown", 10));
#endif
    timer_ = create_wall_timer(
      std::chrono::milliseconds(REPORT_PERIOD_MS), [this]() {status_pub_->publish(std_msgs::msg::String());});
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  std::vector<rclcpp::Publisher<std_msgs::msg::Float32>::SharedPtr> wheel_pubs_;
  rclcpp::TimerBase::SharedPtr timer_;
};

}  // namespace rover_base

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<rover_base::StatusReporter>());
  rclcpp::shutdown();
  return 0;
}
