#include "crawler_base/crawler_base.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<crawler::CrawlerBase>());
  rclcpp::shutdown();
  return 0;
}
