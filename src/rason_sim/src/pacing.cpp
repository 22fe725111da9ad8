#include "rason_sim/pacing.h"

#include <algorithm>
#include <thread>

namespace rason_sim {

WallPacer::Turn WallPacer::next(double t, WallClock::time_point now) {
  const WallClock::time_point due = wall_base_ + wallSeconds((t - t_base_) / factor_);
  const double late = std::chrono::duration<double>(now - due).count();
  if (late > kSlack) {
    wall_base_ = now;
    t_base_ = t;
    lost_ += late;
    return {now, late};
  }
  return {due, 0.0};
}

double WallPacer::wait(double t) {
  const Turn turn = next(t, WallClock::now());
  if (turn.written_off > 0.0) return turn.written_off;
  std::this_thread::sleep_until(turn.due);
  return 0.0;
}

void LockstepPace::onFrameProcessed(double wall_seconds) {
  frame_wall_ = frame_wall_ <= 0.0 ? wall_seconds : 0.8 * frame_wall_ + 0.2 * wall_seconds;
  factor_ = std::clamp(1.0 / (camera_rate_ * kMargin * std::max(frame_wall_, 1e-4)), kMinFactor, max_factor_);
}

}  // namespace rason_sim
