// A goal filled in a test: its field's value says nothing about the server's port names.
#include <memory>
#include <string>

#include "gtest/gtest.h"

namespace deep_controller
{
struct FollowGoal
{
  std::string pose_topic;
};
}  // namespace deep_controller

TEST(Follow, goalNamesATopic)
{
  deep_controller::FollowGoal goal_msg;
  goal_msg.pose_topic = "dynamic_pose";
  EXPECT_EQ(goal_msg.pose_topic, "dynamic_pose");
}
