#pragma once

#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"

namespace depot_map
{

class ResetService;

// A map of one depot. Built as a component it is "depot_map"; built by name, it takes the name.
class DepotMap : public rclcpp::Node
{
public:
  explicit DepotMap(const rclcpp::NodeOptions & options);
  explicit DepotMap(const std::string & name);
  ~DepotMap() override;

  std::string getName() const {return name_;}

private:
  void start();

  std::string name_;
  std::unique_ptr<ResetService> reset_;
};

}  // namespace depot_map
