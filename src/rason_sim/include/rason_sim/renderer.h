// Offscreen CPU rendering of a MuJoCo camera through OSMesa (Mesa's software rasteriser),
// so the simulator runs headless with no display or GPU. A camera's view is taken in two
// parts: the scene at an instant (SceneSnapshot, no GL, on the simulation thread) and its
// drawing (OffscreenRenderer, on the thread whose GL context it made).
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <vector>

namespace rason_sim {

// What camera `camera_id` sees of the world in data, as a list of geoms to draw.
class SceneSnapshot {
 public:
  explicit SceneSnapshot(const mjModel* model);
  ~SceneSnapshot();
  SceneSnapshot(const SceneSnapshot&) = delete;
  SceneSnapshot& operator=(const SceneSnapshot&) = delete;

  void take(const mjModel* model, mjData* data, int camera_id);
  mjvScene& scene() { return scene_; }

 private:
  mjvScene scene_;
  mjvOption option_;
  mjvPerturb perturb_;
  mjvCamera camera_;
};

class OffscreenRenderer {
 public:
  // Makes a GL context current on the calling thread: render on that thread only.
  // Throws std::runtime_error when no GL context can be made.
  OffscreenRenderer(const mjModel* model, int width, int height);
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  // Draws a snapshot; rgb is width*height*3, depth width*height, both bottom-up.
  void render(mjvScene& scene, std::vector<unsigned char>& rgb, std::vector<float>& depth);

  // Near and far clipping planes (metres) of the depth buffer.
  double nearPlane() const { return near_; }
  double farPlane() const { return far_; }

 private:
  struct GlContext;
  std::unique_ptr<GlContext> gl_;
  int width_, height_;
  double near_, far_;
  mjrContext context_;
};

}  // namespace rason_sim
