#include <memory>

#include "example_interfaces/action/fibonacci.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"

namespace comm_demo
{

class FibonacciServer : public rclcpp::Node
{
public:
  using Fibonacci = example_interfaces::action::Fibonacci;
  using GoalHandle = rclcpp_action::ServerGoalHandle<Fibonacci>;

  FibonacciServer()
  : Node("fibonacci_server")
  {
    using namespace std::placeholders;
    server_ = rclcpp_action::create_server<Fibonacci>(
      this,
      "fibonacci",
      std::bind(&FibonacciServer::handle_goal, this, _1, _2),
      std::bind(&FibonacciServer::handle_cancel, this, _1),
      std::bind(&FibonacciServer::handle_accepted, this, _1));
    legacy_server_ = rclcpp_action::create_server<Fibonacci>(
      get_node_base_interface(), get_node_clock_interface(),
      get_node_logging_interface(), get_node_waitables_interface(),
      "fibonacci_legacy",
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const Fibonacci::Goal>) {
        return rclcpp_action::GoalResponse::REJECT;
      },
      [](const std::shared_ptr<GoalHandle>) {return rclcpp_action::CancelResponse::ACCEPT;},
      [](const std::shared_ptr<GoalHandle>) {});
  }

private:
  rclcpp_action::GoalResponse handle_goal(
    const rclcpp_action::GoalUUID &, std::shared_ptr<const Fibonacci::Goal>)
  {
    return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
  }
  rclcpp_action::CancelResponse handle_cancel(const std::shared_ptr<GoalHandle>)
  {
    return rclcpp_action::CancelResponse::ACCEPT;
  }
  void handle_accepted(const std::shared_ptr<GoalHandle>) {}

  rclcpp_action::Server<Fibonacci>::SharedPtr server_;
  rclcpp_action::Server<Fibonacci>::SharedPtr legacy_server_;
};

class FibonacciClient : public rclcpp::Node
{
public:
  FibonacciClient()
  : Node("fibonacci_client")
  {
    client_ = rclcpp_action::create_client<example_interfaces::action::Fibonacci>(
      this, "fibonacci");
  }

private:
  rclcpp_action::Client<example_interfaces::action::Fibonacci>::SharedPtr client_;
};

}  // namespace comm_demo

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::executors::SingleThreadedExecutor executor;
  auto server = std::make_shared<comm_demo::FibonacciServer>();
  auto client = std::make_shared<comm_demo::FibonacciClient>();
  executor.add_node(server);
  executor.add_node(client);
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
