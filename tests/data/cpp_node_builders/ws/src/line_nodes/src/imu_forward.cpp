#include "line_nodes/stages.hpp"

#include "sensor_msgs/msg/imu.hpp"

namespace line_nodes
{

// A pass stage fixed to IMU messages: its ports are the template's, typed here.
class ImuForward : public PassStage<sensor_msgs::msg::Imu>
{
public:
  explicit ImuForward(const rclcpp::NodeOptions & options)
  : PassStage<sensor_msgs::msg::Imu>(
      StageSettings{.node_name = "imu_forward", .input_topic = "imu_raw", .output_topic = "imu"},
      options)
  {
  }
};

}  // namespace line_nodes

int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<line_nodes::ImuForward>(rclcpp::NodeOptions()));
  rclcpp::shutdown();
  return 0;
}
