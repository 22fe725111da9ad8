// Differential-drive kinematics of a Kobuki-like base: twist -> wheel speeds, and
// odometry integrated from the wheels' rotation (what kobuki_node does with its encoders).
#pragma once

#include <algorithm>
#include <cmath>

#include "rason_sim/world.h"

namespace rason_sim {

// Kobuki's limits: 0.7 m/s, 180 deg/s.
constexpr double kMaxLinear = 0.7;
constexpr double kMaxAngular = 3.14159265358979323846;

struct WheelSpeeds {
  double left = 0.0, right = 0.0;  // rad/s, positive drives forward
};

inline WheelSpeeds wheelSpeedsFor(double linear, double angular, const BaseGeometry& base) {
  linear = std::clamp(linear, -kMaxLinear, kMaxLinear);
  angular = std::clamp(angular, -kMaxAngular, kMaxAngular);
  const double half_track = base.wheel_separation / 2.0;
  return {(linear - angular * half_track) / base.wheel_radius,
          (linear + angular * half_track) / base.wheel_radius};
}

// With wheel slip the motor controller still holds each encoder at the commanded speed, but
// the wheel's contact with the floor rolls only (1 - slip) as far: the simulated wheel
// joint (which rolls without slipping) turns at ground speed, and the encoder reads more.
inline WheelSpeeds groundSpeeds(const WheelSpeeds& commanded, const WheelSlip& slip) {
  return {commanded.left * (1.0 - slip.left), commanded.right * (1.0 - slip.right)};
}

// What a wheel's encoder reads (rad) when its contact with the floor rolled `rolled` rad.
inline double encoderAngle(double rolled, double slip) {
  return rolled / (1.0 - slip);
}

inline double normalizeAngle(double a) {
  return std::atan2(std::sin(a), std::cos(a));
}

// Integrates wheel angle increments (midpoint rule) into a planar pose in the odom frame,
// which starts at the robot's start pose = origin, like kobuki_node's.
class WheelOdometry {
 public:
  explicit WheelOdometry(const BaseGeometry& base) : base_(base) {}

  // Absolute wheel angles (rad) at time t (s).
  void update(double left_angle, double right_angle, double t) {
    if (!started_) {
      started_ = true;
    } else {
      const double dl = (left_angle - left_) * base_.wheel_radius;
      const double dr = (right_angle - right_) * base_.wheel_radius;
      const double ds = (dl + dr) / 2.0;
      const double dyaw = (dr - dl) / base_.wheel_separation;
      x_ += ds * std::cos(yaw_ + dyaw / 2.0);
      y_ += ds * std::sin(yaw_ + dyaw / 2.0);
      yaw_ = normalizeAngle(yaw_ + dyaw);
      const double dt = t - time_;
      if (dt > 0.0) {
        linear_ = ds / dt;
        angular_ = dyaw / dt;
      }
    }
    left_ = left_angle;
    right_ = right_angle;
    time_ = t;
  }

  double x() const { return x_; }
  double y() const { return y_; }
  double yaw() const { return yaw_; }
  double linear() const { return linear_; }
  double angular() const { return angular_; }

 private:
  BaseGeometry base_;
  bool started_ = false;
  double left_ = 0.0, right_ = 0.0, time_ = 0.0;
  double x_ = 0.0, y_ = 0.0, yaw_ = 0.0, linear_ = 0.0, angular_ = 0.0;
};

// Kobuki's wheels run a velocity loop with zero steady-state error; MuJoCo's velocity
// servo is proportional only, so add an integral correction to its set point.
inline double servoSetPoint(double target, double measured, double& integral, double dt) {
  constexpr double kIntegralGain = 8.0, kMaxCorrection = 4.0;  // 1/s, rad/s
  if (target == 0.0) {
    integral = 0.0;  // stopping: no wind-up carried into the next motion
    return 0.0;
  }
  integral = std::clamp(integral + (target - measured) * dt, -kMaxCorrection / kIntegralGain,
                        kMaxCorrection / kIntegralGain);
  return target + kIntegralGain * integral;
}

}  // namespace rason_sim
