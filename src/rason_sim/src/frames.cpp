#include "rason_sim/frames.h"

#include <cmath>

namespace rason_sim {

geometry_msgs::Quaternion yawQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2.0);
  q.w = std::cos(yaw / 2.0);
  return q;
}

geometry_msgs::TransformStamped worldToOdom(const std::string& robot, const Pose2D& world_base,
                                            const WheelOdometry& odom) {
  const double yaw = world_base.yaw - odom.yaw();
  const double c = std::cos(yaw), s = std::sin(yaw);
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time(0);
  t.header.frame_id = "world";
  t.child_frame_id = robot + "/odom";
  t.transform.translation.x = world_base.x - (c * odom.x() - s * odom.y());
  t.transform.translation.y = world_base.y - (s * odom.x() + c * odom.y());
  t.transform.rotation = yawQuaternion(yaw);
  return t;
}

geometry_msgs::TransformStamped baseToOpticalFrame(const std::string& robot, const CameraConfig& camera) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time(0);
  t.header.frame_id = robot + "/base_footprint";
  t.child_frame_id = robot + "/camera_rgb_optical_frame";
  t.transform.translation.x = camera.forward_m;
  t.transform.translation.z = camera.height_m;
  t.transform.rotation.x = -0.5;
  t.transform.rotation.y = 0.5;
  t.transform.rotation.z = -0.5;
  t.transform.rotation.w = 0.5;
  return t;
}

}  // namespace rason_sim
