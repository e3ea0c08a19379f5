#pragma once

#include <memory>
#include <string>
#include <message_filters/subscriber.h>
#include <message_filters/sync_policies/approximate_time.h>
#include <message_filters/synchronizer.h>
#include <rclcpp/rclcpp.hpp>

namespace pose_fuser
{
// Subscribes to two topics given by name and hands each matching pair on: a helper object
// whose subscriptions are made through the aliases of its own template.
template <typename First, typename Second>
class Paired
{
public:
  using FirstSub = message_filters::Subscriber<First>;
  using SecondSub = message_filters::Subscriber<Second>;
  using Policy = message_filters::sync_policies::ApproximateTime<First, Second>;

  Paired(rclcpp::Node * node, const std::string & first_topic, const std::string & second_topic)
  {
    first_ = std::make_shared<FirstSub>(node, first_topic);
    second_ = std::make_shared<SecondSub>(node, second_topic);
    sync_ = std::make_shared<message_filters::Synchronizer<Policy>>(Policy(20), *first_, *second_);
  }

private:
  std::shared_ptr<FirstSub> first_;
  std::shared_ptr<SecondSub> second_;
  std::shared_ptr<message_filters::Synchronizer<Policy>> sync_;
};
}  // namespace pose_fuser
