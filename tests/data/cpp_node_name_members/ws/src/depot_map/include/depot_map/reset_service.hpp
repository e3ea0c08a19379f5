#pragma once

#include "depot_map/depot_map.hpp"
#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/trigger.hpp"

namespace depot_map
{

// Offers a service that clears the map it is given; the service is named after that map.
class ResetService
{
public:
  ResetService(rclcpp::Node * node, DepotMap & map);

private:
  DepotMap & map_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr service_;
};

}  // namespace depot_map
