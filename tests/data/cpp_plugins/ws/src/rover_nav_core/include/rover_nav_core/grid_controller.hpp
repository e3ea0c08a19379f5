#pragma once

#include <string>
#include "rover_nav_core/controller.hpp"

namespace rover_nav_core
{
// A controller that keeps an occupancy grid of its own, which its server shows.
class GridController : public Controller
{
public:
  std::string getName() const {return grid_name_;}

protected:
  std::string grid_name_;
};
}  // namespace rover_nav_core
