#include <memory>

#include "example_interfaces/srv/add_two_ints.hpp"
#include "rclcpp/rclcpp.hpp"

using AddTwoInts = example_interfaces::srv::AddTwoInts;
using rclcpp::Node;

// Service server and client in one node; `Node` comes from `using rclcpp::Node`.
class Adder : public Node
{
public:
  typedef example_interfaces::srv::AddTwoInts Sum;

  Adder()
  : Node("adder")
  {
    server_ = create_service<AddTwoInts>(
      "add_two_ints",
      std::bind(&Adder::handle_add, this, std::placeholders::_1, std::placeholders::_2));
    client_ = this->create_client<Sum>("remote/add_two_ints");
  }

private:
  void handle_add(
    const std::shared_ptr<AddTwoInts::Request> request,
    std::shared_ptr<AddTwoInts::Response> response)
  {
    response->sum = request->a + request->b;
  }

  rclcpp::Service<AddTwoInts>::SharedPtr server_;
  rclcpp::Client<Sum>::SharedPtr client_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = Adder::make_shared();
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
