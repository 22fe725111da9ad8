// Lockstep: the simulation loop waits (wall clock, with a timeout) for the nodes that consume
// what it publishes to report it done. Reports arrive on a thread of their own; these classes
// are what the two threads share. No ROS here: the node subscribes and calls onDone/onTick.
#pragma once

#include <condition_variable>
#include <mutex>

#include "rason_sim/control_ticks.h"
#include "rason_sim/pacing.h"

namespace rason_sim {

// The stamp (sim s) of the last message published to a consumer and of the newest one the
// consumer reported done, with the wall times of both: a camera frame and vision_synth's
// robots_seen, stamped as the frame; odometry and the fault injector's odom_filtered,
// stamped as the odometry. Wall times are passed in, so done's is when the report came,
// not when the simulation loop next looked.
class StampReports {
 public:
  void onSent(double t, WallClock::time_point wall) {
    sent_ = t;
    sent_wall_ = wall;
  }
  void onDone(double stamp, WallClock::time_point wall);

  bool outstanding() const { return sent_ >= 0.0; }
  // nothing outstanding, or a report at least as new as the message sent
  bool isDone() const { return sent_ < 0.0 || done_ >= sent_ - kEpsilon; }

  // Ends the wait for the message outstanding (nothing is outstanding afterwards): the wall
  // seconds from sending it to its report (> 0), or -1 when it was not reported (given up).
  double finish();

 private:
  static constexpr double kEpsilon = 1e-6;
  double sent_ = -1.0, done_ = -1.0;
  WallClock::time_point sent_wall_, done_wall_;
};

// StampReports shared by the report thread (onDone) and the simulation loop.
class StampAck {
 public:
  void onSent(double t);
  void onDone(double stamp);

  // Waits (wall clock, up to timeout s) until the consumer has reported the last message
  // sent to it done. Returns the wall seconds it took, 0 when nothing was outstanding, or
  // -1 when it timed out (the message is then given up).
  double awaitDone(double timeout);

 private:
  std::mutex mutex_;
  std::condition_variable reported_;
  StampReports reports_;
};

// The robot's controller's reported ticks (control_ticks.h), shared by the report thread
// (onTick) and the simulation loop.
class ControlAck {
 public:
  explicit ControlAck(double period) : ticks_(period) {}

  void onTick(double stamp, bool commands_motion);

  // Before stepping from now: waits until no unreported tick is due, at most until deadline.
  // False when it timed out: then the controller is given up (ControlTicks::giveUp) and
  // *due is the time of the tick that did not come.
  bool awaitTick(double now, WallClock::time_point deadline, double* due);

  bool stopPending();
  void stopReached();

 private:
  std::mutex mutex_;
  std::condition_variable reported_;
  ControlTicks ticks_;
};

}  // namespace rason_sim
