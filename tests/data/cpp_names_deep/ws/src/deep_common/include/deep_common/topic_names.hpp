// Names every package of the robot agrees on, defined once.
#pragma once

#include <string>

namespace deep_common
{

constexpr char kAlarmTopic[] = "alarm";
const std::string STATUS_TOPIC = "status";
static constexpr auto kRobotPrefix = "robot";

namespace names
{
struct Topics
{
  static constexpr const char * kHeartbeat = "heartbeat";
};
}  // namespace names

}  // namespace deep_common
