// Keeps a room at its target temperature; every parameter is declared with rclcpp's own calls.
#include <rcl_interfaces/msg/parameter_descriptor.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>

namespace climate
{
class Thermostat : public rclcpp::Node
{
public:
  Thermostat()
  : Node("thermostat")
  {
    declare_parameter("target_temperature", 21.5);
    declare_parameter<std::string>("sensor_frame", "room");
    declare_parameter("zones", std::vector<std::string>{"living", "kitchen"});
    declare_parameter("heater_count", rclcpp::ParameterType::PARAMETER_INTEGER);

    rcl_interfaces::msg::ParameterDescriptor fan;
    fan.description = "Fan speed step";
    rcl_interfaces::msg::IntegerRange steps;
    steps.from_value = 0;
    steps.to_value = 10;
    steps.step = 2;
    fan.integer_range.push_back(steps);
    declare_parameter("fan_speed", 4, fan);

    rcl_interfaces::msg::ParameterDescriptor fixed;
    fixed.read_only = true;
    declare_parameter("unit", std::string("celsius"), fixed);

    declare_parameters<double>("pid", {{"kp", 1.2}, {"ki", 0.05}});
    get_parameter_or("hysteresis", hysteresis_, 0.5);
    declare_parameter("legacy_mode", false);
    undeclare_parameter("legacy_mode");

    heat_pub_ = create_publisher<std_msgs::msg::Float64>("heat_demand", 10);
  }

private:
  double hysteresis_{0.0};
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr heat_pub_;
};
}  // namespace climate

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<climate::Thermostat>());
  rclcpp::shutdown();
  return 0;
}
