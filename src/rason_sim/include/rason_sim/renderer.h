// Offscreen CPU rendering of a MuJoCo camera through OSMesa (Mesa's software rasteriser),
// so the simulator runs headless with no display or GPU.
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <vector>

namespace rason_sim {

class OffscreenRenderer {
 public:
  // Throws std::runtime_error when no GL context can be made.
  OffscreenRenderer(const mjModel* model, int width, int height);
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  // Renders camera `camera_id`; rgb is width*height*3, depth width*height, both bottom-up.
  void render(const mjModel* model, mjData* data, int camera_id, std::vector<unsigned char>& rgb,
              std::vector<float>& depth);

  // Near and far clipping planes (metres) of the depth buffer.
  double nearPlane() const { return near_; }
  double farPlane() const { return far_; }

 private:
  struct GlContext;
  std::unique_ptr<GlContext> gl_;
  int width_, height_;
  double near_, far_;
  mjvScene scene_;
  mjrContext context_;
  mjvOption option_;
  mjvPerturb perturb_;
  mjvCamera camera_;
};

}  // namespace rason_sim
