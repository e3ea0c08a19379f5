#include <memory>
#include <mutex>
#include <string>

#include <image_transport/camera_publisher.hpp>
#include <image_transport/image_transport.hpp>
#include <image_transport/subscriber_filter.hpp>
#include <message_filters/subscriber.h>
#include <message_filters/sync_policies/exact_time.h>
#include <message_filters/synchronizer.h>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_components/register_node_macro.hpp>
#include <sensor_msgs/msg/camera_info.hpp>
#include <sensor_msgs/msg/image.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>

namespace depth_tools
{

// Joins a depth image with a brightness image. It subscribes only while somebody listens to
// its cloud: the inputs are made in the publisher's matched callback, by names resolved first
// so that remaps reach the image transport.
class ShadedCloudNode : public rclcpp::Node
{
public:
  explicit ShadedCloudNode(const rclcpp::NodeOptions & options)
  : Node("shaded_cloud", options)
  {
    rclcpp::PublisherOptions pub_options;
    pub_options.event_callbacks.matched_callback =
      [this](rclcpp::MatchedInfo & info)
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (info.current_count == 0) {
          depth_sub_.unsubscribe();
          shade_sub_.unsubscribe();
          shade_info_sub_.unsubscribe();
          return;
        }
        auto base = get_node_base_interface();
        const std::string depth = base->resolve_topic_or_service_name("depth/image_rect", false);
        const std::string shade = base->resolve_topic_or_service_name("shade/image_rect", false);
        const std::string shade_info = base->resolve_topic_or_service_name(
          image_transport::getCameraInfoTopic(shade), false);
        depth_sub_.subscribe(this, depth, "raw");
        shade_sub_.subscribe(this, shade, "raw");
        shade_info_sub_.subscribe(this, shade_info);
      };
    cloud_pub_ = create_publisher<sensor_msgs::msg::PointCloud2>("points", 1, pub_options);
    // A preview with its camera info beside it (`preview/camera_info`).
    preview_pub_ = image_transport::create_camera_publisher(
      this, get_node_base_interface()->resolve_topic_or_service_name("preview/image_raw", false));
  }

private:
  std::mutex mutex_;
  // Two image inputs declared together.
  image_transport::SubscriberFilter depth_sub_, shade_sub_;
  message_filters::Subscriber<sensor_msgs::msg::CameraInfo> shade_info_sub_;
  rclcpp::Publisher<sensor_msgs::msg::PointCloud2>::SharedPtr cloud_pub_;
  image_transport::CameraPublisher preview_pub_;
};

}  // namespace depth_tools

RCLCPP_COMPONENTS_REGISTER_NODE(depth_tools::ShadedCloudNode)
