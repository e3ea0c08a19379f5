// Smooths velocity commands; its parameters are declared in every way rclcpp and nav2_util offer.
#include <geometry_msgs/msg/twist.hpp>
#include <nav2_util/node_utils.hpp>
#include <rcl_interfaces/msg/parameter_descriptor.hpp>
#include <rclcpp/rclcpp.hpp>

namespace drive_servers
{
// Declares one switch per sensor kind under the prefix it is handed.
void declareSources(rclcpp::Node & node, const std::string & prefix)
{
  for (const std::string kind : {"scan", "pointcloud"}) {
    node.declare_parameter<bool>(prefix + kind, false);
  }
}

// Gathers the feedback gains; it declares them on the node it is given.
class FeedbackParameters
{
public:
  explicit FeedbackParameters(rclcpp::Node * node)
  {
    gain_ = node->declare_parameter("feedback_gain", 0.8);
  }

private:
  double gain_{0.0};
};

class SpeedLimiter : public rclcpp::Node
{
public:
  SpeedLimiter()
  : Node("speed_limiter")
  {
    declare_parameter("smoothing_frequency", 20.0);
    declare_parameter<std::string>("feedback", "OPEN_LOOP");
    declare_parameter("max_velocity", std::vector<double>{0.5, 0.0, 2.5});
    declare_parameter("window", 5);
    // a type and no default: the launch must give it
    declare_parameter("wheel_base", rclcpp::ParameterType::PARAMETER_DOUBLE);

    rcl_interfaces::msg::ParameterDescriptor scale;
    scale.description = "Factor applied to every command";
    rcl_interfaces::msg::FloatingPointRange bounds;
    bounds.from_value = 0.0;
    bounds.to_value = 2.0;
    scale.floating_point_range.push_back(bounds);
    declare_parameter("scale_velocities", 1.0, scale);

    rcl_interfaces::msg::ParameterDescriptor fixed;
    fixed.read_only = true;
    fixed.description = "Frame the commands are given in";
    declare_parameter("command_frame", std::string("base_link"), fixed);

    auto node = shared_from_this();
    nav2_util::declare_parameter_if_not_declared(
      node, "odom_topic", rclcpp::ParameterValue(std::string("odom")));
    nav2_util::declare_parameter_if_not_declared(
      node, "odom_duration", rclcpp::ParameterValue(0.1));
    get_parameter_or("deadband", deadband_, 0.01);
    declare_parameter("legacy_mode", false);
    undeclare_parameter("legacy_mode");
    declare_parameters<double>("limits", {{"max_accel", 2.5}, {"max_decel", -2.5}});
    // a map built elsewhere: its keys are not written here
    std::map<std::string, int> tuning{{"filter_taps", 5}};
    declare_parameters("tuning", tuning);
    declareSources(*this, "sources.");
    feedback_ = std::make_unique<FeedbackParameters>(this);

    const auto topic = get_parameter("odom_topic").as_string();
    odom_sub_ = create_subscription<geometry_msgs::msg::Twist>(
      topic, 10, [](geometry_msgs::msg::Twist::ConstSharedPtr) {});
    cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel_smoothed", 10);
  }

private:
  double deadband_{0.0};
  std::unique_ptr<FeedbackParameters> feedback_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr odom_sub_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr cmd_pub_;
};
}  // namespace drive_servers

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<drive_servers::SpeedLimiter>());
  rclcpp::shutdown();
  return 0;
}
