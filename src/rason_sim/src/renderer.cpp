#include "rason_sim/renderer.h"

#include <GL/osmesa.h>

#include <stdexcept>

namespace rason_sim {

SceneSnapshot::SceneSnapshot(const mjModel* model) {
  mjv_defaultScene(&scene_);
  mjv_defaultOption(&option_);
  mjv_defaultPerturb(&perturb_);
  mjv_defaultCamera(&camera_);
  mjv_makeScene(model, &scene_, 2000);
}

SceneSnapshot::~SceneSnapshot() { mjv_freeScene(&scene_); }

void SceneSnapshot::take(const mjModel* model, mjData* data, int camera_id) {
  camera_.type = mjCAMERA_FIXED;
  camera_.fixedcamid = camera_id;
  mjv_updateScene(model, data, &option_, &perturb_, &camera_, mjCAT_ALL, &scene_);
}

struct OffscreenRenderer::GlContext {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> buffer;  // OSMesa's default framebuffer; MuJoCo draws to its own FBO
};

OffscreenRenderer::OffscreenRenderer(const mjModel* model, int width, int height)
    : gl_(new GlContext), width_(width), height_(height) {
  gl_->context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 8, nullptr);
  if (!gl_->context) throw std::runtime_error("OSMesaCreateContextExt failed");
  gl_->buffer.resize(static_cast<size_t>(width) * height * 4);
  if (!OSMesaMakeCurrent(gl_->context, gl_->buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(gl_->context);
    throw std::runtime_error("OSMesaMakeCurrent failed");
  }
  mjr_defaultContext(&context_);
  mjr_makeContext(model, &context_, mjFONTSCALE_50);
  if (context_.offWidth < width || context_.offHeight < height) {
    mjr_freeContext(&context_);
    OSMesaDestroyContext(gl_->context);
    throw std::runtime_error("offscreen buffer smaller than the camera image");
  }
  mjr_setBuffer(mjFB_OFFSCREEN, &context_);
  near_ = model->vis.map.znear * model->stat.extent;
  far_ = model->vis.map.zfar * model->stat.extent;
}

OffscreenRenderer::~OffscreenRenderer() {
  mjr_freeContext(&context_);
  if (gl_->context) OSMesaDestroyContext(gl_->context);
}

void OffscreenRenderer::render(mjvScene& scene, std::vector<unsigned char>& rgb, std::vector<float>& depth) {
  const mjrRect viewport = {0, 0, width_, height_};
  mjr_render(viewport, &scene, &context_);
  rgb.resize(static_cast<size_t>(width_) * height_ * 3);
  depth.resize(static_cast<size_t>(width_) * height_);
  mjr_readPixels(rgb.data(), depth.data(), viewport, &context_);
}

}  // namespace rason_sim
