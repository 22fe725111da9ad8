#include "rason_sim/depth_camera.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace rason_sim {

Intrinsics intrinsicsFor(const CameraConfig& camera) {
  Intrinsics k;
  k.width = camera.width;
  k.height = camera.height;
  const double half_h = camera.horizontal_fov_deg * 3.14159265358979323846 / 360.0;
  k.fx = k.fy = (camera.width / 2.0) / std::tan(half_h);  // square pixels, as MuJoCo renders
  k.cx = (camera.width - 1) / 2.0;
  k.cy = (camera.height - 1) / 2.0;
  return k;
}

float linearDepth(float buffer, double near, double far) {
  if (!(buffer < 1.0f)) return std::numeric_limits<float>::quiet_NaN();  // background
  return static_cast<float>(near * far / (far - buffer * (far - near)));
}

double kinectSigma(double z) {
  // Axial noise model of the Kinect v1 (Nguyen et al. 2012): 1.2 mm + 1.9 mm per (m - 0.4)^2.
  return 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4);
}

namespace {

// Inverse of the standard normal CDF at p (0 < p < 1), by bisection: exact enough for a
// table built once.
double inverseNormalCdf(double p) {
  double lo = -9.0, hi = 9.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

constexpr int kGaussBits = 16;

const std::vector<float>& gaussTable() {
  static const std::vector<float> table = [] {
    const int n = 1 << kGaussBits;
    std::vector<float> t(n);
    for (int i = 0; i < n / 2; ++i) {  // symmetric: the lower half mirrored
      t[i] = static_cast<float>(inverseNormalCdf((i + 0.5) / n));
      t[n - 1 - i] = -t[i];
    }
    return t;
  }();
  return table;
}

}  // namespace

void PixelNoise::reseed(uint64_t seed) {
  // splitmix64 of the seed: a well-mixed state, never 0 (xorshift's one fixed point)
  uint64_t z = seed + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  state_ = (z ^ (z >> 31)) | 1ULL;
  gauss_table_ = gaussTable().data();  // built now, not in the first frame
}

void PixelNoise::draw(float& gauss, float& uniform) {
  state_ ^= state_ >> 12;
  state_ ^= state_ << 25;
  state_ ^= state_ >> 27;
  const uint64_t r = state_ * 0x2545F4914F6CDD1DULL;
  gauss = gauss_table_[r >> (64 - kGaussBits)];
  uniform = static_cast<float>(r & 0xFFFFFFULL) * (1.0f / 16777216.0f);  // 24 other bits
}

void buildFrame(const Intrinsics& k, const uint8_t* rgb_bottom_up, const float* depth_bottom_up,
                double near, double far, const DepthNoise& noise, PixelNoise& rng,
                std::vector<uint8_t>& image, std::vector<uint16_t>& depth_mm,
                std::vector<uint8_t>* cloud) {
  const int w = k.width, h = k.height;
  image.resize(static_cast<size_t>(w) * h * 3);
  depth_mm.resize(static_cast<size_t>(w) * h);
  if (cloud) cloud->resize(static_cast<size_t>(w) * h * kPointStep);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int row = 0; row < h; ++row) {
    const int src_row = h - 1 - row;  // OpenGL rows start at the bottom
    const uint8_t* src_rgb = rgb_bottom_up + static_cast<size_t>(src_row) * w * 3;
    std::memcpy(&image[static_cast<size_t>(row) * w * 3], src_rgb, static_cast<size_t>(w) * 3);
    const float* src_depth = depth_bottom_up + static_cast<size_t>(src_row) * w;
    uint16_t* out_mm = &depth_mm[static_cast<size_t>(row) * w];
    uint8_t* out = cloud ? &(*cloud)[static_cast<size_t>(row) * w * kPointStep] : nullptr;
    for (int col = 0; col < w; ++col) {
      float z = linearDepth(src_depth[col], near, far);
      if (!std::isnan(z)) {
        float gauss, uniform;
        rng.draw(gauss, uniform);
        if (noise.scale > 0.0) z += static_cast<float>(noise.scale * kinectSigma(z)) * gauss;
        if (z < noise.min_range || z > noise.max_range) z = nan;
        if (noise.dropout > 0.0 && uniform < noise.dropout) z = nan;
      }
      // max_range (8 m) is far below 65.535 m: the rounded millimetres fit
      out_mm[col] = std::isnan(z) ? 0 : static_cast<uint16_t>(std::lround(z * 1000.0f));
      if (!out) continue;
      float xyz[3] = {nan, nan, nan};
      if (!std::isnan(z)) {
        xyz[0] = static_cast<float>((col - k.cx) * z / k.fx);
        xyz[1] = static_cast<float>((row - k.cy) * z / k.fy);
        xyz[2] = z;
      }
      // PCL packs colour as 0x00RRGGBB in the bytes of a float.
      const uint32_t packed = (uint32_t(src_rgb[col * 3]) << 16) |
                              (uint32_t(src_rgb[col * 3 + 1]) << 8) | uint32_t(src_rgb[col * 3 + 2]);
      std::memcpy(out, xyz, sizeof(xyz));
      std::memcpy(out + 12, &packed, 4);
      out += kPointStep;
    }
  }
}

}  // namespace rason_sim
