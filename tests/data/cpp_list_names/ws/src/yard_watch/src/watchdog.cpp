#include <memory>
#include <string>
#include <vector>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/string.hpp"
#include "yard_watch/heartbeat_probe.hpp"

// Supervises the nodes named in `watched_nodes` and reports, per yard zone, whether it is
// occupied. Both lists come from the parameters the launch file gives.
class Watchdog : public rclcpp::Node
{
public:
  Watchdog()
  : Node("watchdog")
  {
    watched_ = declare_parameter<std::vector<std::string>>(
      "watched_nodes", std::vector<std::string>{});
    zones_ = declare_parameter<std::vector<std::string>>("zones", std::vector<std::string>{});
    alarm_pub_ = create_publisher<std_msgs::msg::String>("alarms", 10);
    // One summary per namespace, and a state topic under the node's own full name.
    summary_pub_ = create_publisher<std_msgs::msg::String>(
      std::string(get_namespace()) + "/watch_summary", 10);
    state_pub_ = create_publisher<std_msgs::msg::String>(
      std::string(this->get_fully_qualified_name()) + "/state", 1);
    createProbes();
    for (const auto & zone : zones_) {
      zone_pubs_.push_back(
        create_publisher<std_msgs::msg::Bool>("zone/" + zone + "/occupied", 10));
    }
  }

private:
  void createProbes()
  {
    for (const std::string & name : watched_) {
      probes_.push_back(std::make_shared<yard_watch::HeartbeatProbe>(name, this));
    }
  }

  std::vector<std::string> watched_;
  std::vector<std::string> zones_;
  std::vector<std::shared_ptr<yard_watch::HeartbeatProbe>> probes_;
  std::vector<rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr> zone_pubs_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr alarm_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr summary_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr state_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Watchdog>());
  rclcpp::shutdown();
  return 0;
}
