// The tf frames of a robot: where its odometry frame lies in the world, and its camera's
// optical frame on the base. Message building only: nothing here needs a ROS master.
#pragma once

#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/TransformStamped.h>

#include <string>

#include "rason_sim/diff_drive.h"
#include "rason_sim/world.h"

namespace rason_sim {

// a rotation by yaw about z
geometry_msgs::Quaternion yawQuaternion(double yaw);

// world -> <robot>/odom: where the robot's odometry frame lies in the world, so rviz (fixed
// frame world) can show each robot's odometry beside its true pose. At the start it is the
// start pose; a set_pose moves the robot, not its odometry, so the frame is worked out again.
geometry_msgs::TransformStamped worldToOdom(const std::string& robot, const Pose2D& world_base,
                                            const WheelOdometry& odom);

// <robot>/base_footprint -> <robot>/camera_rgb_optical_frame (z forward, x right, y down)
geometry_msgs::TransformStamped baseToOpticalFrame(const std::string& robot, const CameraConfig& camera);

}  // namespace rason_sim
