// Lockstep with a robot's controller: when the simulation loop must wait for a tick report,
// or for a stop to reach the base.
#include <gtest/gtest.h>

#include "rason_sim/control_ticks.h"

namespace rason_sim {
namespace {

constexpr double kPeriod = 0.02;  // motion_decomp's 50 Hz

TEST(ControlTicks, AStandingRobotsControllerIsNeverWaitedFor) {
  ControlTicks ticks(kPeriod);
  EXPECT_FALSE(ticks.tickDue(0.0));
  EXPECT_FALSE(ticks.tickDue(100.0));
  ticks.onTick(1.0, false);  // an idle report (motion_decomp's 1 Hz odom_commanded)
  EXPECT_FALSE(ticks.tickDue(5.0));
  EXPECT_FALSE(ticks.stopPending());
}

TEST(ControlTicks, WhileMovingTheNextTickIsDueOnePeriodAfterTheLast) {
  ControlTicks ticks(kPeriod);
  ticks.onTick(2.00, true);
  EXPECT_FALSE(ticks.tickDue(2.00));
  EXPECT_FALSE(ticks.tickDue(2.01));
  EXPECT_TRUE(ticks.tickDue(2.02));  // the clock has reached the next tick: it can fire
  EXPECT_TRUE(ticks.tickDue(2.05));
  ticks.onTick(2.02, true);
  EXPECT_FALSE(ticks.tickDue(2.03));
  EXPECT_TRUE(ticks.tickDue(2.04));
}

TEST(ControlTicks, ATickFiredLateSetsTheNextDueTime) {
  ControlTicks ticks(kPeriod);
  ticks.onTick(3.00, true);
  ticks.onTick(3.03, true);  // fired a step late
  EXPECT_FALSE(ticks.tickDue(3.04));
  EXPECT_TRUE(ticks.tickDue(3.05));
}

TEST(ControlTicks, AStopAfterMotionIsPendingUntilTheBaseHasIt) {
  ControlTicks ticks(kPeriod);
  ticks.onTick(1.00, true);
  ticks.onTick(1.02, false);
  EXPECT_TRUE(ticks.stopPending());
  EXPECT_FALSE(ticks.tickDue(1.50));  // stopped: no more ticks waited for
  ticks.stopReached();
  EXPECT_FALSE(ticks.stopPending());
  ticks.onTick(1.04, false);  // standing still is no new stop
  EXPECT_FALSE(ticks.stopPending());
}

TEST(ControlTicks, AReportOlderThanTheNewestChangesNothing) {
  ControlTicks ticks(kPeriod);
  ticks.onTick(4.00, true);
  ticks.onTick(4.02, true);
  ticks.onTick(4.00, false);  // reordered on the way
  EXPECT_FALSE(ticks.stopPending());
  EXPECT_TRUE(ticks.tickDue(4.04));
  EXPECT_DOUBLE_EQ(ticks.last(), 4.02);
}

TEST(ControlTicks, GivingUpEndsTheWaitsUntilTheControllerMovesTheRobotAgain) {
  ControlTicks ticks(kPeriod);
  ticks.onTick(5.00, true);
  ticks.onTick(5.02, false);
  ticks.giveUp();
  EXPECT_FALSE(ticks.stopPending());
  EXPECT_FALSE(ticks.tickDue(9.00));
  ticks.onTick(9.00, true);
  EXPECT_TRUE(ticks.tickDue(9.02));
}

}  // namespace
}  // namespace rason_sim

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
