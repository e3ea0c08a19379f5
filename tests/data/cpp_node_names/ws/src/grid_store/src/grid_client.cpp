#include <nav_msgs/srv/get_map.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

// Asks the main store for its grid and watches its status.
class GridClient : public rclcpp::Node
{
public:
  GridClient()
  : Node("grid_client")
  {
    client_ = create_client<nav_msgs::srv::GetMap>("/grid_store/grid");
    status_sub_ = create_subscription<std_msgs::msg::String>(
      "/grid_store/status", 1, [](std_msgs::msg::String::ConstSharedPtr) {});
  }

private:
  rclcpp::Client<nav_msgs::srv::GetMap>::SharedPtr client_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr status_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<GridClient>());
  rclcpp::shutdown();
  return 0;
}
