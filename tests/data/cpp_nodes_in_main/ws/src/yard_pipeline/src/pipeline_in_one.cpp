#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "yard_pipeline/stages.hpp"

// Builds the three stages in one process, so that frames pass between them without copies.
int main(int argc, char * argv[])
{
  rclcpp::init(argc, argv);
  rclcpp::executors::SingleThreadedExecutor executor;
  rclcpp::NodeOptions options;
  options.use_intra_process_comms(true);

  auto camera = std::make_shared<yard_pipeline::CameraStage>(options);
  executor.add_node(camera);
  auto marker = std::make_shared<yard_pipeline::MarkerStage>(options);
  executor.add_node(marker);
  yard_pipeline::DisplayStage * display = new yard_pipeline::DisplayStage(options);
  executor.add_node(display->get_node_base_interface());

  executor.spin();
  rclcpp::shutdown();
  delete display;
  return 0;
}
