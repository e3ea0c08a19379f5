// Topic names shared by the rover's nodes.
#ifndef ROVER_BASE__TOPICS_HPP_
#define ROVER_BASE__TOPICS_HPP_

#define ROVER_ODOM_TOPIC "odom"
#define ROVER_CMD_TOPIC "cmd_vel"
#define ROVER_STATUS_TOPIC ROVER_NAMESPACE "status"
#define ROVER_NAMESPACE "rover/"

// Four or six wheels: the six-wheel chassis reports its middle axle too.
#define ROVER_WHEELS 6

#endif  // ROVER_BASE__TOPICS_HPP_
