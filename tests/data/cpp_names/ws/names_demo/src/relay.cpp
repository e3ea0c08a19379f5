#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
#include "std_srvs/srv/trigger.hpp"

namespace names_demo
{

static const std::string kStatusTopic = "status";

using StringMsg = std_msgs::msg::String;

class Relay : public rclcpp::Node
{
public:
  Relay()
  : Node("relay"), output_topic_("relayed")
  {
    std::string local_topic = "local_in";
    in_sub_ = create_subscription<StringMsg>(local_topic, 10, std::bind(&Relay::on_in, this, std::placeholders::_1));
    out_pub_ = create_publisher<StringMsg>(output_topic_, 10);
    echo_pub_ = create_publisher<StringMsg>(echo_topic_, 10);

    this->declare_parameter<std::string>("alarm_topic", "alarm");
    this->get_parameter("alarm_topic", alarm_topic_);
    alarm_pub_ = create_publisher<StringMsg>(alarm_topic_, 1);

    auto debug_topic = this->declare_parameter("debug_topic", "debug");
    debug_pub_ = create_publisher<StringMsg>(debug_topic, 1);

    declare_parameter("log_topic", rclcpp::ParameterValue("log"));
    log_pub_ = create_publisher<StringMsg>(get_parameter("log_topic").as_string(), 1);

    bool use_service = this->declare_parameter("use_service", false);
    if (use_service) {
      reset_srv_ = create_service<std_srvs::srv::Trigger>(
        "~/reset", std::bind(&Relay::on_reset, this, std::placeholders::_1, std::placeholders::_2));
    } else {
      reset_sub_ = create_subscription<StringMsg>("~/reset", 1, std::bind(&Relay::on_in, this, std::placeholders::_1));
    }

    status_pub_ = create_publisher<StringMsg>(kStatusTopic, 1);
    named_pub_ = create_publisher<StringMsg>(std::string(get_name()) + "/heartbeat", 1);
  }

  void configure()
  {
    late_topic_ = "late";
    late_pub_ = create_publisher<StringMsg>(late_topic_, 1);
  }

private:
  void on_in(const StringMsg::SharedPtr msg) {out_pub_->publish(*msg);}
  void on_reset(
    const std::shared_ptr<std_srvs::srv::Trigger::Request>,
    std::shared_ptr<std_srvs::srv::Trigger::Response>) {}

  std::string output_topic_;
  std::string echo_topic_ = "echo";
  std::string alarm_topic_;
  std::string late_topic_;
  rclcpp::Subscription<StringMsg>::SharedPtr in_sub_, reset_sub_;
  rclcpp::Publisher<StringMsg>::SharedPtr out_pub_, echo_pub_, alarm_pub_, debug_pub_, log_pub_;
  rclcpp::Publisher<StringMsg>::SharedPtr status_pub_, named_pub_, late_pub_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr reset_srv_;
};

}  // namespace names_demo

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<names_demo::Relay>());
  rclcpp::shutdown();
  return 0;
}
