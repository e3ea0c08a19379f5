// Surveys a site; helper code declares its parameters on the node it is handed.
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

namespace survey
{
// Declares the motion limits under the prefix it is given.
void declareLimits(rclcpp::Node * node, const std::string & prefix)
{
  node->declare_parameter(prefix + "max_speed", 0.8);
  node->declare_parameter(prefix + "max_turn", 1.2);
}

// Reads the sensor calibration from the node it is built with.
struct Calibration
{
  explicit Calibration(rclcpp::Node * node)
  {
    offset = node->declare_parameter("calibration.offset", 0.02);
  }
  double offset{0.0};
};

struct ReportSettings
{
  double period{1.0};
};

class Surveyor : public rclcpp::Node
{
public:
  Surveyor()
  : Node("surveyor")
  {
    declareLimits(this, "limits.");
    calibration_ = std::make_unique<Calibration>(this);
    settings_.period = declare_parameter("report_period", 5.0);
    report_pub_ = create_publisher<std_msgs::msg::String>("survey_report", 10);
  }

private:
  std::unique_ptr<Calibration> calibration_;
  ReportSettings settings_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr report_pub_;
};
}  // namespace survey

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<survey::Surveyor>());
  rclcpp::shutdown();
  return 0;
}
