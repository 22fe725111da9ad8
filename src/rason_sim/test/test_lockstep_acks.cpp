// Lockstep's acknowledgements: what counts as reported done, how long a message took, and the
// waits with their timeouts, across the report thread and the simulation loop. No ROS.
#include <gtest/gtest.h>

#include <thread>

#include "rason_sim/lockstep_acks.h"

namespace rason_sim {
namespace {

const WallClock::time_point kStart{};

WallClock::time_point at(double wall_seconds) { return kStart + wallSeconds(wall_seconds); }

TEST(StampReports, NothingSentIsNothingToWaitFor) {
  StampReports reports;
  EXPECT_FALSE(reports.outstanding());
  EXPECT_TRUE(reports.isDone());
}

TEST(StampReports, AMessageIsDoneWhenAReportAtLeastAsNewComes) {
  StampReports reports;
  reports.onSent(2.0, at(10.0));
  EXPECT_TRUE(reports.outstanding());
  EXPECT_FALSE(reports.isDone());
  reports.onDone(1.9, at(10.02));  // the message before
  EXPECT_FALSE(reports.isDone());
  reports.onDone(2.0, at(10.09));
  EXPECT_TRUE(reports.isDone());
  EXPECT_NEAR(reports.finish(), 0.09, 1e-9);  // from sending to the report that did it
  EXPECT_FALSE(reports.outstanding());
}

TEST(StampReports, ALaterReportDoesNotMoveWhenTheMessageWasDone) {
  StampReports reports;
  reports.onSent(3.0, at(1.0));
  reports.onDone(3.0, at(1.05));
  reports.onDone(3.1, at(1.50));  // the next message's report, before the loop looked
  EXPECT_NEAR(reports.finish(), 0.05, 1e-9);
}

TEST(StampReports, AReportAheadOfTheMessageCountsAtOnce) {
  StampReports reports;
  reports.onDone(5.0, at(0.5));
  reports.onSent(4.0, at(1.0));
  EXPECT_TRUE(reports.isDone());
}

TEST(StampReports, AnUnreportedMessageIsGivenUp) {
  StampReports reports;
  reports.onSent(1.0, at(0.0));
  EXPECT_EQ(reports.finish(), -1.0);
  EXPECT_FALSE(reports.outstanding());
  EXPECT_TRUE(reports.isDone());
}

TEST(StampAck, AwaitingNothingOutstandingReturnsZero) {
  StampAck ack;
  EXPECT_EQ(ack.awaitDone(10.0), 0.0);
  ack.onDone(1.0);  // a report with nothing sent
  EXPECT_EQ(ack.awaitDone(10.0), 0.0);
}

TEST(StampAck, AMessageReportedBeforeTheWaitTookItsTimeToReport) {
  StampAck ack;
  ack.onSent(1.0);
  ack.onDone(1.0);
  EXPECT_GT(ack.awaitDone(10.0), 0.0);
  EXPECT_EQ(ack.awaitDone(10.0), 0.0);  // nothing outstanding any more
}

TEST(StampAck, AReportFromAnotherThreadEndsTheWait) {
  StampAck ack;
  ack.onSent(2.0);
  std::thread reporter([&ack] { ack.onDone(2.0); });
  const double took = ack.awaitDone(30.0);
  reporter.join();
  EXPECT_GT(took, 0.0);
  EXPECT_LT(took, 30.0);
}

TEST(StampAck, AWaitWithoutAReportTimesOutAndGivesTheMessageUp) {
  StampAck ack;
  ack.onSent(3.0);
  ack.onDone(2.9);  // an older message's report
  const auto before = WallClock::now();
  EXPECT_EQ(ack.awaitDone(0.02), -1.0);
  EXPECT_GE(WallClock::now() - before, wallSeconds(0.02));
  EXPECT_EQ(ack.awaitDone(10.0), 0.0);  // given up: not waited for again
}

constexpr double kPeriod = 0.02;

TEST(ControlAck, NoTickDueMeansNoWait) {
  ControlAck ack(kPeriod);
  double due = -1.0;
  EXPECT_TRUE(ack.awaitTick(1.0, at(0.0), &due));  // a deadline long past does not matter
  ack.onTick(1.0, true);
  EXPECT_TRUE(ack.awaitTick(1.01, at(0.0), &due));
  EXPECT_EQ(due, -1.0);
}

TEST(ControlAck, AMissingTickTimesOutAndTheControllerIsGivenUp) {
  ControlAck ack(kPeriod);
  ack.onTick(1.0, true);
  double due = 0.0;
  EXPECT_FALSE(ack.awaitTick(1.02, WallClock::now() + wallSeconds(0.02), &due));
  EXPECT_NEAR(due, 1.02, 1e-9);
  EXPECT_TRUE(ack.awaitTick(5.0, at(0.0), &due));  // given up until it reports a motion
  ack.onTick(5.0, true);
  EXPECT_FALSE(ack.awaitTick(5.02, at(0.0), &due));
}

TEST(ControlAck, ATickFromAnotherThreadEndsTheWait) {
  ControlAck ack(kPeriod);
  ack.onTick(2.0, true);
  std::thread controller([&ack] { ack.onTick(2.02, true); });
  const bool reported = ack.awaitTick(2.02, WallClock::now() + wallSeconds(30.0), nullptr);
  controller.join();
  EXPECT_TRUE(reported);
}

TEST(ControlAck, AStopIsPendingUntilReached) {
  ControlAck ack(kPeriod);
  ack.onTick(1.0, true);
  ack.onTick(1.02, false);
  EXPECT_TRUE(ack.stopPending());
  EXPECT_TRUE(ack.awaitTick(1.04, at(0.0), nullptr));  // a stopped robot's ticks are not waited for
  ack.stopReached();
  EXPECT_FALSE(ack.stopPending());
}

}  // namespace
}  // namespace rason_sim

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
