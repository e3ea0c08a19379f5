#include "depot_map/depot_map.hpp"
#include "depot_map/reset_service.hpp"

namespace depot_map
{

DepotMap::DepotMap(const rclcpp::NodeOptions & options)
: Node("depot_map", options),
  name_("depot_map")
{
  start();
}

DepotMap::DepotMap(const std::string & name)
: Node(name),
  name_(name)
{
  start();
}

DepotMap::~DepotMap() = default;

void DepotMap::start()
{
  reset_ = std::make_unique<ResetService>(this, *this);
}

}  // namespace depot_map
