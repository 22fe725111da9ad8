// The base's kinematics: twist -> wheel speeds, wheel slip, and odometry from the encoders.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "rason_sim/diff_drive.h"

namespace rason_sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Drives the two wheels' floor contacts at constant speeds (rad/s) for `seconds`, feeding
// the encoders (with slip) to odometry every 20 ms like the simulator's 50 Hz; returns
// the true travel of the base's centre, integrated as the odometry is but from the floor.
Pose2D drive(WheelOdometry& odometry, const BaseGeometry& base, WheelSpeeds commanded,
             const WheelSlip& slip, double seconds) {
  const WheelSpeeds ground = groundSpeeds(commanded, slip);
  WheelOdometry truth(base);
  const double dt = 0.02;
  for (int i = 0; i <= static_cast<int>(std::lround(seconds / dt)); ++i) {
    const double t = i * dt;
    odometry.update(encoderAngle(ground.left * t, slip.left),
                    encoderAngle(ground.right * t, slip.right), t);
    truth.update(ground.left * t, ground.right * t, t);
  }
  return {truth.x(), truth.y(), truth.yaw()};
}

TEST(WheelSpeeds, ForwardAndTurning) {
  const BaseGeometry base;
  const WheelSpeeds straight = wheelSpeedsFor(0.2, 0.0, base);
  EXPECT_NEAR(straight.left, 0.2 / base.wheel_radius, 1e-12);
  EXPECT_NEAR(straight.right, straight.left, 1e-12);
  const WheelSpeeds left_turn = wheelSpeedsFor(0.0, 1.0, base);
  EXPECT_NEAR(left_turn.right, -left_turn.left, 1e-12);
  EXPECT_GT(left_turn.right, 0.0);  // counter-clockwise: the right wheel drives forward
  const WheelSpeeds limited = wheelSpeedsFor(5.0, 0.0, base);
  EXPECT_NEAR(limited.left * base.wheel_radius, kMaxLinear, 1e-12);
}

TEST(WheelOdometry, WithoutSlipItFollowsTheFloor) {
  const BaseGeometry base;
  WheelOdometry odometry(base);
  const Pose2D truth = drive(odometry, base, wheelSpeedsFor(0.2, 0.0, base), WheelSlip{}, 5.0);
  EXPECT_NEAR(truth.x, 1.0, 1e-9);
  EXPECT_NEAR(odometry.x(), truth.x, 1e-9);
  EXPECT_NEAR(odometry.y(), 0.0, 1e-9);
  EXPECT_NEAR(odometry.linear(), 0.2, 1e-9);
}

TEST(WheelOdometry, SlipMakesOdometryOverestimateTheTravel) {
  const BaseGeometry base;
  WheelOdometry odometry(base);
  const WheelSlip slip{0.05, 0.05};
  const Pose2D truth = drive(odometry, base, wheelSpeedsFor(0.2, 0.0, base), slip, 5.0);
  EXPECT_NEAR(odometry.x(), 1.0, 1e-9);      // the encoders turned as commanded
  EXPECT_NEAR(odometry.linear(), 0.2, 1e-9);  // and report the commanded speed
  EXPECT_NEAR(truth.x, 0.95, 1e-9);          // the floor saw 5 % less
  EXPECT_NEAR(truth.yaw, 0.0, 1e-12);        // equal slip: still straight
}

TEST(WheelOdometry, UnequalSlipCurvesAPathOdometryCallsStraight) {
  const BaseGeometry base;
  WheelOdometry odometry(base);
  const WheelSlip slip{0.03, 0.01};  // the left wheel slips more: the robot veers left
  const Pose2D truth = drive(odometry, base, wheelSpeedsFor(0.2, 0.0, base), slip, 5.0);
  EXPECT_NEAR(odometry.yaw(), 0.0, 1e-12);
  EXPECT_NEAR(truth.yaw, (0.03 - 0.01) * 1.0 / base.wheel_separation, 1e-9);
  EXPECT_GT(truth.y, 0.0);
}

TEST(WheelOdometry, SlipShortensATurnInPlace) {
  const BaseGeometry base;
  WheelOdometry odometry(base);
  const WheelSlip slip{0.04, 0.04};
  const Pose2D truth = drive(odometry, base, wheelSpeedsFor(0.0, kPi / 4, base), slip, 2.0);
  EXPECT_NEAR(odometry.yaw(), kPi / 2, 1e-9);
  EXPECT_NEAR(truth.yaw, 0.96 * kPi / 2, 1e-9);
}

TEST(WheelServo, AWheelAtItsSpeedGetsItsSpeed) {
  double integral = 0.0;
  EXPECT_EQ(servoSetPoint(5.0, 5.0, integral, 0.01), 5.0);
  EXPECT_EQ(integral, 0.0);
}

TEST(WheelServo, ALaggingWheelIsPushedHarderUpToALimit) {
  double integral = 0.0;
  const double first = servoSetPoint(5.0, 4.0, integral, 0.01);  // 1 rad/s short for 10 ms
  EXPECT_NEAR(first, 5.0 + 8.0 * 0.01, 1e-12);
  const double second = servoSetPoint(5.0, 4.0, integral, 0.01);
  EXPECT_GT(second, first);
  for (int i = 0; i < 1000; ++i) servoSetPoint(5.0, 0.0, integral, 0.01);  // stalled
  EXPECT_NEAR(servoSetPoint(5.0, 0.0, integral, 0.01), 5.0 + 4.0, 1e-12);
  EXPECT_NEAR(servoSetPoint(-5.0, 0.0, integral, 10.0), -5.0 - 4.0, 1e-12);  // and backwards
}

TEST(WheelServo, StoppingCarriesNoWindUpIntoTheNextMotion) {
  double integral = 0.0;
  for (int i = 0; i < 100; ++i) servoSetPoint(5.0, 0.0, integral, 0.01);
  EXPECT_EQ(servoSetPoint(0.0, 3.0, integral, 0.01), 0.0);
  EXPECT_EQ(integral, 0.0);
  EXPECT_EQ(servoSetPoint(2.0, 2.0, integral, 0.01), 2.0);
}

TEST(WorldConfig, WheelSlipMustBeInRange) {
  WorldConfig world;
  RobotConfig robot;
  robot.name = "faulty";
  world.robots.push_back(robot);
  EXPECT_NO_THROW(validate(world));
  for (double bad : {-0.01, 0.5, std::nan("")}) {
    world.robots[0].slip.right = bad;
    EXPECT_THROW(validate(world), std::invalid_argument) << bad;
  }
}

}  // namespace
}  // namespace rason_sim

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
