// Camera frames drawn on a thread of their own, so the simulation steps on while a frame is
// rendered, turned into images and published (the costly part: software rendering of every
// camera). The simulation thread takes each frame's snapshot at the frame's time; the worker
// draws the frames in the order they were submitted and hands each to its callback there.
// No ROS here: the callback publishes.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "rason_sim/renderer.h"

namespace rason_sim {

class CameraWorker {
 public:
  // The drawn frame (bottom-up, as OffscreenRenderer gives it) and the depth buffer's planes.
  using Done = std::function<void(const std::vector<unsigned char>& rgb, const std::vector<float>& depth,
                                  double near, double far)>;

  // One slot per camera; starts the thread, which makes the GL context. Throws
  // std::runtime_error (the thread's) when it cannot.
  CameraWorker(const mjModel* model, int width, int height, int slots);
  ~CameraWorker();  // draws what was submitted, then ends the thread
  CameraWorker(const CameraWorker&) = delete;
  CameraWorker& operator=(const CameraWorker&) = delete;

  // Waits until slot's last frame is done (its callback returned).
  void waitIdle(int slot);

  // After waitIdle(slot): the scene of camera_id in data now, to be drawn and given to done.
  void submit(int slot, const mjModel* model, mjData* data, int camera_id, Done done);

 private:
  void run(const mjModel* model, int width, int height);

  std::vector<std::unique_ptr<SceneSnapshot>> snapshots_;
  std::vector<bool> busy_;
  std::deque<std::pair<int, Done>> queue_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool started_ = false, stopping_ = false;
  std::exception_ptr start_error_;
  std::thread thread_;
};

}  // namespace rason_sim
