// How fast simulated time runs against the wall clock: at a real-time factor (WallPacer), or,
// with lockstep at factor 0, at the pace the camera frames are processed (LockstepPace).
// No ROS here: wall times are passed in as values.
#pragma once

#include <chrono>

namespace rason_sim {

using WallClock = std::chrono::steady_clock;

// seconds as a steady_clock duration
inline WallClock::duration wallSeconds(double seconds) {
  return std::chrono::duration_cast<WallClock::duration>(std::chrono::duration<double>(seconds));
}

// Paces simulated time against the wall clock at a real-time factor, as a ceiling: when
// the CPU falls behind, the lost wall time is written off instead of caught up, because a
// burst of simulated seconds in a moment of wall time leaves every node that runs on
// wall-clock CPU (camera pipeline, controllers, agents) seconds behind the world
// (a helper found a robot in a frame 2 s old and turned past it).
class WallPacer {
 public:
  static constexpr double kSlack = 0.05;  // s of wall time

  WallPacer(double real_time_factor, WallClock::time_point start)
      : factor_(real_time_factor), wall_base_(start) {}

  // When simulated time t is due, seen at wall time now.
  struct Turn {
    WallClock::time_point due;  // sleep until then (already past when late)
    double written_off;         // wall seconds given up now (0 when on time)
  };

  // Lateness within the slack is caught up, so sleep jitter does not slow the simulation
  // down; beyond it, the pace starts again from (now, t).
  Turn next(double t, WallClock::time_point now);

  // next() on the steady clock, sleeping until t is due; returns the wall seconds written off.
  double wait(double t);

  double lost() const { return lost_; }  // wall seconds written off so far

 private:
  double factor_;
  WallClock::time_point wall_base_;
  double t_base_ = 0.0;
  double lost_ = 0.0;
};

// With lockstep at factor 0: a camera period in (a little more than) the wall time the
// consumer took for the last frames, smoothed, between kMinFactor and a ceiling. The camera
// is not the only consumer on wall-clock CPU: the decomposer's control loop and the agents
// fall behind the world when a run alone goes much faster than real time (at 4.35x a 10
// degree turn ended 13-16 degrees on), hence the ceiling.
class LockstepPace {
 public:
  static constexpr double kMargin = 1.1, kMinFactor = 0.2;

  LockstepPace(double camera_rate, double max_factor) : camera_rate_(camera_rate), max_factor_(max_factor) {}

  // A frame's consumer reported it done wall_seconds (> 0) after it was published.
  void onFrameProcessed(double wall_seconds);

  // times real time, 1 before the first frame is reported
  double factor() const { return factor_; }

  // Wall seconds a simulation step of step_seconds takes: its share of a frame's processing,
  // or about real time while not every camera's consumer is up (nodes starting).
  double stepWallSeconds(double step_seconds, bool consumers_up) const {
    return step_seconds / (consumers_up ? factor_ : 1.0);
  }

 private:
  double camera_rate_, max_factor_;
  double frame_wall_ = 0.0;  // s of wall time a frame's processing takes (smoothed)
  double factor_ = 1.0;
};

}  // namespace rason_sim
