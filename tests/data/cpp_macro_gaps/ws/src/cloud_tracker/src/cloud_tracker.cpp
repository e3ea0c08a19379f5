#include "cloud_tracker/cloud_tracker.hpp"

#include <memory>
#include <typeinfo>

namespace cloud_tracker
{
CloudTracker::CloudTracker()
: Node("cloud_tracker")
{
  TRACE_SCOPE(this)
  cloud_sub_ = create_subscription<Cloud>(
    "points", rclcpp::SensorDataQoS(),
    [this](const Cloud::ConstSharedPtr cloud) { dispatch(cloud); });
  distance_pub_ = create_publisher<Distance>("centroid_distance", 10);
}

void CloudTracker::on_cloud(const Cloud::ConstSharedPtr & cloud)
{
  TRACE_SCOPE(this)
  const rclcpp::Time & stamp(cloud->header.stamp);
  if (typeid(centroid_(0)) == typeid(float) && stamp.nanoseconds() > 0) {
    Distance distance;
    distance.data = centroid_.norm();
    distance_pub_->publish(distance);
  }
}
}  // namespace cloud_tracker

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<cloud_tracker::CloudTracker>());
  rclcpp::shutdown();
  return 0;
}
