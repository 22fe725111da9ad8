// The robots' tf frames: world -> odom puts the odometry's pose where the robot is, and the
// camera's optical frame looks along the base's x axis. No master.
#include <gtest/gtest.h>

#include <cmath>

#include "rason_sim/frames.h"

namespace rason_sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// yaw of a rotation about z
double yawOf(const geometry_msgs::Quaternion& q) { return 2.0 * std::atan2(q.z, q.w); }

// a pose in the odom frame, seen through world -> odom
Pose2D inWorld(const geometry_msgs::TransformStamped& world_to_odom, double x, double y, double yaw) {
  const double rot = yawOf(world_to_odom.transform.rotation);
  const double c = std::cos(rot), s = std::sin(rot);
  return {world_to_odom.transform.translation.x + c * x - s * y,
          world_to_odom.transform.translation.y + s * x + c * y, normalizeAngle(rot + yaw)};
}

TEST(Frames, YawQuaternionIsARotationAboutZ) {
  const geometry_msgs::Quaternion q = yawQuaternion(kPi / 2.0);
  EXPECT_EQ(q.x, 0.0);
  EXPECT_EQ(q.y, 0.0);
  EXPECT_NEAR(q.z, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(q.w, std::sqrt(0.5), 1e-12);
}

TEST(Frames, AtTheStartTheOdometryFrameIsTheStartPose) {
  const WheelOdometry odom{BaseGeometry()};
  const geometry_msgs::TransformStamped t = worldToOdom("faulty", {-1.0, 0.75, 0.3}, odom);
  EXPECT_EQ(t.header.frame_id, "world");
  EXPECT_EQ(t.child_frame_id, "faulty/odom");
  EXPECT_NEAR(t.transform.translation.x, -1.0, 1e-12);
  EXPECT_NEAR(t.transform.translation.y, 0.75, 1e-12);
  EXPECT_NEAR(yawOf(t.transform.rotation), 0.3, 1e-12);
}

TEST(Frames, AfterATeleportTheOdometrysPoseLandsWhereTheRobotIs) {
  WheelOdometry odom{BaseGeometry()};
  odom.update(0.0, 0.0, 0.0);
  odom.update(10.0, 14.0, 2.0);  // drove a curve: odometry is somewhere off its origin
  const Pose2D moved{2.0, -1.0, -2.5};  // set_pose put the robot here
  const Pose2D seen = inWorld(worldToOdom("faulty", moved, odom), odom.x(), odom.y(), odom.yaw());
  EXPECT_NEAR(seen.x, moved.x, 1e-9);
  EXPECT_NEAR(seen.y, moved.y, 1e-9);
  EXPECT_NEAR(normalizeAngle(seen.yaw - moved.yaw), 0.0, 1e-9);
}

TEST(Frames, TheOpticalFrameLooksAlongTheBasesXAxis) {
  CameraConfig camera;
  const geometry_msgs::TransformStamped t = baseToOpticalFrame("helper", camera);
  EXPECT_EQ(t.header.frame_id, "helper/base_footprint");
  EXPECT_EQ(t.child_frame_id, "helper/camera_rgb_optical_frame");
  EXPECT_EQ(t.transform.translation.x, camera.forward_m);
  EXPECT_EQ(t.transform.translation.z, camera.height_m);
  // the optical z axis (forward) in the base frame: rotate (0, 0, 1) by the quaternion
  const auto& q = t.transform.rotation;
  const double zx = 2.0 * (q.x * q.z + q.w * q.y);
  const double zy = 2.0 * (q.y * q.z - q.w * q.x);
  const double zz = 1.0 - 2.0 * (q.x * q.x + q.y * q.y);
  EXPECT_NEAR(zx, 1.0, 1e-12);
  EXPECT_NEAR(zy, 0.0, 1e-12);
  EXPECT_NEAR(zz, 0.0, 1e-12);
  // the optical x axis (right in the image) is the base's -y
  const double xy = 2.0 * (q.x * q.y + q.w * q.z);
  EXPECT_NEAR(xy, -1.0, 1e-12);
}

}  // namespace
}  // namespace rason_sim

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
