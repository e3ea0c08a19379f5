#include "depot_map/reset_service.hpp"

namespace depot_map
{

ResetService::ResetService(rclcpp::Node * node, DepotMap & map)
: map_(map)
{
  service_ = node->create_service<std_srvs::srv::Trigger>(
    std::string("reset_") + map_.getName(),
    [](std_srvs::srv::Trigger::Request::SharedPtr, std_srvs::srv::Trigger::Response::SharedPtr) {});
}

}  // namespace depot_map
