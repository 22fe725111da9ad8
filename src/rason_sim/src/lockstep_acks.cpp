#include "rason_sim/lockstep_acks.h"

#include <algorithm>

namespace rason_sim {

void StampReports::onDone(double stamp, WallClock::time_point wall) {
  if (!isDone() && stamp >= sent_ - kEpsilon) done_wall_ = wall;
  done_ = std::max(done_, stamp);
}

double StampReports::finish() {
  const bool done = isDone();
  sent_ = -1.0;
  if (!done) return -1.0;
  return std::max(std::chrono::duration<double>(done_wall_ - sent_wall_).count(), 1e-9);
}

void StampAck::onSent(double t) {
  std::lock_guard<std::mutex> lock(mutex_);
  reports_.onSent(t, WallClock::now());
}

void StampAck::onDone(double stamp) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    reports_.onDone(stamp, WallClock::now());
  }
  reported_.notify_all();
}

double StampAck::awaitDone(double timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!reports_.outstanding()) return 0.0;
  const auto deadline = WallClock::now() + wallSeconds(timeout);
  reported_.wait_until(lock, deadline, [this] { return reports_.isDone(); });
  return reports_.finish();
}

void ControlAck::onTick(double stamp, bool commands_motion) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ticks_.onTick(stamp, commands_motion);
  }
  reported_.notify_all();
}

bool ControlAck::awaitTick(double now, WallClock::time_point deadline, double* due) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (reported_.wait_until(lock, deadline, [this, now] { return !ticks_.tickDue(now); })) return true;
  if (due) *due = ticks_.last() + ticks_.period();
  ticks_.giveUp();
  return false;
}

bool ControlAck::stopPending() {
  std::lock_guard<std::mutex> lock(mutex_);
  return ticks_.stopPending();
}

void ControlAck::stopReached() {
  std::lock_guard<std::mutex> lock(mutex_);
  ticks_.stopReached();
}

}  // namespace rason_sim
