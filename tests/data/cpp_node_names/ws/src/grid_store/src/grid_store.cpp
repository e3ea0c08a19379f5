#include <memory>
#include <nav_msgs/srv/get_map.hpp>
#include <rclcpp/rclcpp.hpp>
#include "grid_store/status_reporter.hpp"

namespace grid_store
{
// Serves its grid under its own node name, so that two stores never collide.
class GridStore : public rclcpp::Node
{
public:
  GridStore()
  : rclcpp::Node("grid_store")
  {
    const std::string prefix = get_name() + std::string("/");
    query_srv_ = create_service<nav_msgs::srv::GetMap>(
      prefix + std::string(query_suffix_),
      [](const std::shared_ptr<nav_msgs::srv::GetMap::Request>,
      std::shared_ptr<nav_msgs::srv::GetMap::Response>) {});
    reporter_ = std::make_unique<StatusReporter>(this);
    // A parameter whose name is built at run time: its default is no parameter name.
    cache_topic_ = declare_parameter(cache_name_ + "." + "topic", std::string("cache_out"));
    cache_pub_ = create_publisher<std_msgs::msg::String>(cache_topic_ + "_updates", 1);
  }

private:
  const std::string query_suffix_{"grid"};
  std::string cache_name_{"cache"};
  std::string cache_topic_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr cache_pub_;
  rclcpp::Service<nav_msgs::srv::GetMap>::SharedPtr query_srv_;
  std::unique_ptr<StatusReporter> reporter_;
};
}  // namespace grid_store

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<grid_store::GridStore>());
  rclcpp::shutdown();
  return 0;
}
