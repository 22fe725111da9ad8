#include "rason_sim/camera_worker.h"

namespace rason_sim {

CameraWorker::CameraWorker(const mjModel* model, int width, int height, int slots) : busy_(slots, false) {
  for (int i = 0; i < slots; ++i) snapshots_.emplace_back(new SceneSnapshot(model));
  thread_ = std::thread([this, model, width, height] { run(model, width, height); });
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return started_; });
  if (start_error_) {
    lock.unlock();
    thread_.join();
    std::rethrow_exception(start_error_);
  }
}

CameraWorker::~CameraWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void CameraWorker::waitIdle(int slot) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this, slot] { return !busy_[slot]; });
}

void CameraWorker::submit(int slot, const mjModel* model, mjData* data, int camera_id, Done done) {
  snapshots_[slot]->take(model, data, camera_id);  // the slot is idle: the worker does not read it
  {
    std::lock_guard<std::mutex> lock(mutex_);
    busy_[slot] = true;
    queue_.emplace_back(slot, std::move(done));
  }
  changed_.notify_all();
}

void CameraWorker::run(const mjModel* model, int width, int height) {
  std::unique_ptr<OffscreenRenderer> renderer;
  try {
    renderer.reset(new OffscreenRenderer(model, width, height));  // GL current on this thread
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    start_error_ = std::current_exception();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    started_ = true;
  }
  changed_.notify_all();
  if (!renderer) return;
  std::vector<unsigned char> rgb;
  std::vector<float> depth;
  while (true) {
    std::pair<int, Done> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping, and nothing left to draw
      job = std::move(queue_.front());
      queue_.pop_front();
    }
    renderer->render(snapshots_[job.first]->scene(), rgb, depth);
    job.second(rgb, depth, renderer->nearPlane(), renderer->farPlane());
    {
      std::lock_guard<std::mutex> lock(mutex_);
      busy_[job.first] = false;
    }
    changed_.notify_all();
  }
}

}  // namespace rason_sim
