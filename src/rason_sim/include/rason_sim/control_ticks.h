// Lockstep with a robot's controller (motion_decomp): what the simulation loop may do
// before its next step, given the ticks the controller reported. No ROS here.
//
// The controller runs on ROS time: a tick due at T fires once /clock reaches T, reads the
// odometry and sends a twist. Under a busy CPU a fast simulation can be many steps past T by
// then, so a turn runs on while the controller is late to stop it. The controller reports
// each tick (odom_commanded, stamped with the tick's time, carrying the twist commanded);
// while a robot is commanded to move, the simulation does not step past the next tick's time
// before that tick is reported, and after a tick that stopped the robot, not before the stop
// reached the base. Seen in simulated time, the controller then acts as promptly at any pace.
#pragma once

namespace rason_sim {

class ControlTicks {
 public:
  // period: the controller's tick period (s of simulated time)
  explicit ControlTicks(double period) : period_(period) {}

  // A tick reported at stamp (s), commanding motion or not (a zero twist). A report older
  // than the newest one (reordered in transport) changes nothing.
  void onTick(double stamp, bool commands_motion) {
    if (stamp < last_ - kEpsilon) return;
    stop_pending_ = moving_ && !commands_motion;
    moving_ = commands_motion;
    last_ = stamp;
  }

  // Before stepping from now: is a tick due that has not been reported? Every tick due by
  // now can fire (the clock has reached now), so waiting for it cannot deadlock: rospy's
  // timer schedules the next tick at most one period after the last one fired.
  bool tickDue(double now) const { return moving_ && now >= last_ + period_ - kEpsilon; }

  // A tick stopped the robot and the base may not have had the zero twist yet.
  bool stopPending() const { return stop_pending_; }

  // The base has the stop (its command is zero), or waiting for it timed out.
  void stopReached() { stop_pending_ = false; }

  // The controller stopped reporting (died, or its reports are lost): stop waiting for it
  // until it reports motion again.
  void giveUp() {
    moving_ = false;
    stop_pending_ = false;
  }

  double last() const { return last_; }
  double period() const { return period_; }

 private:
  static constexpr double kEpsilon = 1e-6;
  double period_;
  double last_ = -1.0;
  bool moving_ = false;
  bool stop_pending_ = false;
};

}  // namespace rason_sim
