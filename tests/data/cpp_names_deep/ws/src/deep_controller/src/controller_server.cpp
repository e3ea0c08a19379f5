// A lifecycle controller server whose port names come from elsewhere: the parameters struct
// its handler fills, another package's constants, and formatted strings.
#include <format>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "deep_common/topic_names.hpp"
#include "deep_controller/parameter_handler.hpp"
#include "geometry_msgs/msg/pose_stamped.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
#include "std_msgs/msg/float64.hpp"
#include "std_msgs/msg/string.hpp"

using namespace deep_common;  // NOLINT

namespace deep_controller
{

using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

struct FollowGoal
{
  std::string pose_topic;
};

class ControllerServer : public rclcpp_lifecycle::LifecycleNode
{
public:
  explicit ControllerServer(const rclcpp::NodeOptions & options)
  : rclcpp_lifecycle::LifecycleNode("controller_server", options)
  {
  }

  CallbackReturn on_configure(const rclcpp_lifecycle::State &) override
  {
    param_handler_ = std::make_unique<ParameterHandler>(shared_from_this());
    params_ = param_handler_->getParams();

    // Fields the handler filled from parameters, with their declared defaults.
    odom_sub_ = create_subscription<nav_msgs::msg::Odometry>(
      params_->odom_topic, 10, [this](nav_msgs::msg::Odometry::ConstSharedPtr) {});
    speed_limit_sub_ = create_subscription<std_msgs::msg::Float64>(
      params_->speed_limit_topic, 10, [this](std_msgs::msg::Float64::ConstSharedPtr) {});
    pose_pub_ = create_publisher<geometry_msgs::msg::PoseStamped>(
      params_->base_frame + "/pose", 10);
    // A field no parameter fills: the struct's own initializer.
    cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>(params_->cmd_topic, 10);

    // Constants of another package's header.
    alarm_pub_ = create_publisher<std_msgs::msg::String>(deep_common::kAlarmTopic, 10);
    status_pub_ = create_publisher<std_msgs::msg::String>(STATUS_TOPIC, 10);
    heartbeat_pub_ =
      create_publisher<std_msgs::msg::String>(deep_common::names::Topics::kHeartbeat, 1);

    // Formatted names.
    const std::string robot = declare_parameter("robot_name", "robot1");
    diagnostics_pub_ =
      create_publisher<std_msgs::msg::String>(std::format("{}/diagnostics", robot), 10);
    const std::string group = "wheels";
    rate_pub_ = create_publisher<std_msgs::msg::Float64>(
      fmt::format("~/{0}/rate_{1}", group, std::to_string(2)), 10);
    prefixed_pub_ = create_publisher<std_msgs::msg::String>(
      std::string(kRobotPrefix) + "/" + std::to_string(1) + "/state", 10);
    return CallbackReturn::SUCCESS;
  }

  // The pose topic of a goal is chosen by whoever sends the goal: no name in code.
  void follow(const std::shared_ptr<const FollowGoal> & request)
  {
    target_sub_ = create_subscription<geometry_msgs::msg::PoseStamped>(
      request->pose_topic, 1, [this](geometry_msgs::msg::PoseStamped::ConstSharedPtr) {});
  }

private:
  std::unique_ptr<ParameterHandler> param_handler_;
  Parameters * params_ = nullptr;
  rclcpp::Subscription<nav_msgs::msg::Odometry>::SharedPtr odom_sub_;
  rclcpp::Subscription<std_msgs::msg::Float64>::SharedPtr speed_limit_sub_;
  rclcpp::Subscription<geometry_msgs::msg::PoseStamped>::SharedPtr target_sub_;
  rclcpp_lifecycle::LifecyclePublisher<geometry_msgs::msg::PoseStamped>::SharedPtr pose_pub_;
  rclcpp_lifecycle::LifecyclePublisher<geometry_msgs::msg::Twist>::SharedPtr cmd_pub_;
  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr alarm_pub_;
  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr status_pub_;
  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr heartbeat_pub_;
  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr diagnostics_pub_;
  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::Float64>::SharedPtr rate_pub_;
  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr prefixed_pub_;
};

}  // namespace deep_controller

RCLCPP_COMPONENTS_REGISTER_NODE(deep_controller::ControllerServer)
