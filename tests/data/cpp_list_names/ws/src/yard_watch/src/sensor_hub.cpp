#include <memory>
#include <string>
#include <vector>

#include "rclcpp/rclcpp.hpp"
#include "yard_watch/feed.hpp"

// Listens to every feed named in `feeds`: a laser feed's topic is a parameter of its own, a
// sonar feed listens to `<name>/range`. `<name>.kind` says which a feed is.
class SensorHub : public rclcpp::Node
{
public:
  SensorHub()
  : Node("sensor_hub")
  {
    const std::vector<std::string> names =
      declare_parameter<std::vector<std::string>>("feeds", std::vector<std::string>{});
    for (std::string name : names) {
      const std::string kind = declare_parameter(name + ".kind", std::string("laser"));
      if (kind == "laser") {
        auto feed = std::make_shared<yard_watch::Feed>(this, name);
        feed->start();
        feeds_.push_back(feed);
      } else if (kind == "sonar") {
        sonars_.push_back(std::make_shared<yard_watch::SonarFeed>(this, name));
      }
    }
  }

private:
  std::vector<std::shared_ptr<yard_watch::Feed>> feeds_;
  std::vector<std::shared_ptr<yard_watch::SonarFeed>> sonars_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<SensorHub>());
  rclcpp::shutdown();
  return 0;
}
