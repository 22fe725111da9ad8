// Turns MuJoCo's offscreen RGB + depth buffers into what a Kinect driver publishes: a
// top-down rgb8 image, the registered depth image (16UC1, millimetres) and an organized
// PointCloud2 (x, y, z, rgb) in the optical frame, with Kinect-like depth noise and dropouts.
#pragma once

#include <cstdint>
#include <vector>

#include "rason_sim/world.h"

namespace rason_sim {

struct Intrinsics {
  int width = 0, height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;
};

Intrinsics intrinsicsFor(const CameraConfig& camera);

struct DepthNoise {
  double scale = 1.0;     // 1 = Kinect-like axial noise; 0 = exact depth
  double dropout = 0.0;   // probability that a valid pixel returns no depth
  double min_range = 0.45, max_range = 8.0;
};

// Depth buffer value (0..1, non-linear) -> metres along the optical axis; NaN = no hit.
float linearDepth(float buffer, double near, double far);

// Kinect v1 axial noise (standard deviation in metres) at a given depth: grows with z^2.
double kinectSigma(double z);

// Random numbers for per-pixel depth noise, ~300 000 draws a frame: one xorshift64* number
// per draw, a standard normal read from a table of its inverse CDF at 2^16 evenly spaced
// probabilities (quantized, |value| < 4.4). std::normal_distribution over std::mt19937 was
// half of the simulator's CPU.
class PixelNoise {
 public:
  explicit PixelNoise(uint64_t seed = 1) { reseed(seed); }
  void reseed(uint64_t seed);
  // a standard normal and, from other bits of the same number, a uniform in [0, 1)
  void draw(float& gauss, float& uniform);

 private:
  uint64_t state_ = 1;
  const float* gauss_table_ = nullptr;
};

constexpr int kPointStep = 16;  // x, y, z, rgb as float32

// rgb_bottom_up: width*height*3 bytes as MuJoCo reads them (first row = bottom).
// depth_bottom_up: width*height floats, depth buffer values.
// Fills image (rgb8, top row first), depth_mm (millimetres along the optical axis, 0 = no
// return, top row first) and, unless cloud is null, cloud (kPointStep bytes per point,
// row-major). The noise drawn is the same whichever outputs are asked for.
void buildFrame(const Intrinsics& k, const uint8_t* rgb_bottom_up, const float* depth_bottom_up,
                double near, double far, const DepthNoise& noise, PixelNoise& rng,
                std::vector<uint8_t>& image, std::vector<uint16_t>& depth_mm,
                std::vector<uint8_t>* cloud);

}  // namespace rason_sim
