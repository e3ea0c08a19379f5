#pragma once

#include <Eigen/Core>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>
#include <std_msgs/msg/float64.hpp>

#include <memory>
#include <type_traits>

#define TRACE_SCOPE(x)

namespace cloud_tracker
{
template <typename T, typename = std::nullptr_t>
struct HasHeader : std::false_type
{
};

// Detects a header member: a comma expression in decltype.
template <typename T>
struct HasHeader<T, decltype((void)T::header, nullptr)> : std::true_type
{
};

class CloudTracker : public rclcpp::Node
{
public:
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
  using Cloud = sensor_msgs::msg::PointCloud2;
  using Distance = std_msgs::msg::Float64;
  using Handler = void (CloudTracker::*)(const Cloud::ConstSharedPtr &);

  CloudTracker();

private:
  void on_cloud(const Cloud::ConstSharedPtr & cloud);
  void dispatch(const Cloud::ConstSharedPtr & cloud) { (this->*handler_)(cloud); }

  Handler handler_{&CloudTracker::on_cloud};
  Eigen::Vector3f centroid_;
  rclcpp::Subscription<Cloud>::SharedPtr cloud_sub_;
  rclcpp::Publisher<Distance>::SharedPtr distance_pub_;
};
}  // namespace cloud_tracker
