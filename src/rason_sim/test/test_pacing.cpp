// Pacing simulated time against the wall clock: at a real-time factor, writing off lateness
// beyond the slack; with lockstep, at the pace frames are processed. Wall times are values.
#include <gtest/gtest.h>

#include "rason_sim/pacing.h"

namespace rason_sim {
namespace {

const WallClock::time_point kStart{};  // the pacer's wall-clock origin

WallClock::time_point at(double wall_seconds) { return kStart + wallSeconds(wall_seconds); }

double secondsOf(WallClock::time_point wall) { return std::chrono::duration<double>(wall - kStart).count(); }

TEST(WallPacer, SimulatedTimeIsDueAtItsShareOfWallTime) {
  WallPacer pacer(2.0, kStart);  // twice real time
  const WallPacer::Turn turn = pacer.next(1.0, at(0.1));
  EXPECT_NEAR(secondsOf(turn.due), 0.5, 1e-9);
  EXPECT_EQ(turn.written_off, 0.0);
  EXPECT_NEAR(secondsOf(pacer.next(3.0, at(0.6)).due), 1.5, 1e-9);
  EXPECT_EQ(pacer.lost(), 0.0);
}

TEST(WallPacer, LatenessWithinTheSlackIsCaughtUp) {
  WallPacer pacer(1.0, kStart);
  const WallPacer::Turn late = pacer.next(1.0, at(1.0 + 0.8 * WallPacer::kSlack));
  EXPECT_NEAR(secondsOf(late.due), 1.0, 1e-9);  // already past: no sleep
  EXPECT_EQ(late.written_off, 0.0);
  EXPECT_NEAR(secondsOf(pacer.next(2.0, at(1.5)).due), 2.0, 1e-9);  // the pace is unchanged
}

TEST(WallPacer, LatenessBeyondTheSlackIsWrittenOffNotCaughtUp) {
  WallPacer pacer(1.0, kStart);
  const WallPacer::Turn late = pacer.next(1.0, at(1.3));
  EXPECT_NEAR(late.written_off, 0.3, 1e-9);
  EXPECT_NEAR(secondsOf(late.due), 1.3, 1e-9);
  EXPECT_NEAR(pacer.lost(), 0.3, 1e-9);
  // the pace starts again from there: simulated 1.5 s is due at wall 1.8 s, not 1.5 s
  EXPECT_NEAR(secondsOf(pacer.next(1.5, at(1.4)).due), 1.8, 1e-9);
  pacer.next(2.0, at(2.5));  // 0.2 s late again
  EXPECT_NEAR(pacer.lost(), 0.5, 1e-9);
}

TEST(WallPacer, WaitOnTheSteadyClockWritesOffWhatIsLate) {
  WallPacer behind(1.0, WallClock::now() - wallSeconds(10.0));
  const double written_off = behind.wait(1.0);  // 9 s late: no sleep
  EXPECT_GE(written_off, 9.0);
  EXPECT_EQ(behind.lost(), written_off);
}

TEST(LockstepPace, RealTimeUntilAFrameIsReported) {
  LockstepPace pace(10.0, 2.5);
  EXPECT_EQ(pace.factor(), 1.0);
  EXPECT_NEAR(pace.stepWallSeconds(0.02, true), 0.02, 1e-12);
}

TEST(LockstepPace, ACameraPeriodTakesALittleMoreThanAFramesProcessing) {
  LockstepPace pace(10.0, 1000.0);
  pace.onFrameProcessed(0.05);  // 50 ms for a 100 ms period: about twice real time
  EXPECT_NEAR(pace.factor(), 1.0 / (10.0 * LockstepPace::kMargin * 0.05), 1e-9);
  EXPECT_NEAR(pace.stepWallSeconds(0.02, true), 0.02 / pace.factor(), 1e-12);
  EXPECT_NEAR(pace.stepWallSeconds(0.02, false), 0.02, 1e-12);  // consumers not all up yet
}

TEST(LockstepPace, TheFramesWallTimeIsSmoothed) {
  LockstepPace pace(10.0, 1000.0);
  pace.onFrameProcessed(0.05);
  pace.onFrameProcessed(0.10);  // 0.8 * 0.05 + 0.2 * 0.10 = 0.06
  EXPECT_NEAR(pace.factor(), 1.0 / (10.0 * LockstepPace::kMargin * 0.06), 1e-9);
}

TEST(LockstepPace, TheFactorStaysBetweenTheFloorAndTheCeiling) {
  LockstepPace fast(10.0, 2.5);
  fast.onFrameProcessed(1e-6);
  EXPECT_EQ(fast.factor(), 2.5);
  LockstepPace slow(10.0, 2.5);
  slow.onFrameProcessed(60.0);
  EXPECT_EQ(slow.factor(), LockstepPace::kMinFactor);
}

}  // namespace
}  // namespace rason_sim

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
