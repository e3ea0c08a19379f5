#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "yard_pipeline/relay_stage.hpp"

// One relay, told at start-up where to send the frames: the two constructions are alternatives.
int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  std::shared_ptr<yard_pipeline::RelayStage> relay;
  if (argc > 1 && std::string(argv[1]) == "--to-marker") {
    relay = std::make_shared<yard_pipeline::RelayStage>("frames", "marked_frames", "switch_relay");
  } else {
    relay = std::make_shared<yard_pipeline::RelayStage>("frames", "raw_copy", "switch_relay");
  }
  rclcpp::spin(relay);
  rclcpp::shutdown();
  return 0;
}
