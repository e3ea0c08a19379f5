#include "pose_fuser/pose_fuser.hpp"

namespace pose_fuser
{
PoseFuser::PoseFuser(const rclcpp::NodeOptions & options)
: rclcpp::Node("pose_fuser", options),
  imu_sub_(this, "input/imu", rclcpp::SensorDataQoS().get_rmw_qos_profile())
{
  // The second input subscribes once the node is built, under its private name, and only
  // when the parameter asks for it.
  use_odometry_ = declare_parameter("use_odometry", true);
  if (use_odometry_) {
    odom_sub_.subscribe(this, "~/input/odometry", rclcpp::QoS{1}.get_rmw_qos_profile());
  }
  sync_ = std::make_shared<message_filters::Synchronizer<SyncPolicy>>(
    SyncPolicy(10), imu_sub_, odom_sub_);
  sync_->registerCallback(std::bind(&PoseFuser::onPair, this, std::placeholders::_1,
    std::placeholders::_2));
  pose_pub_ = create_publisher<geometry_msgs::msg::PoseStamped>("output/pose", 1);
}

void PoseFuser::onPair(const Imu::ConstSharedPtr &, const Odometry::ConstSharedPtr &)
{
}
}  // namespace pose_fuser

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<pose_fuser::PoseFuser>(rclcpp::NodeOptions()));
  rclcpp::shutdown();
  return 0;
}
