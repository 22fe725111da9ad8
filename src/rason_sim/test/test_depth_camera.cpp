// The simulated Kinect's depth noise: its random numbers and what buildFrame makes of them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rason_sim/depth_camera.h"

namespace rason_sim {
namespace {

constexpr int kDraws = 1000000;

TEST(PixelNoise, GaussIsAStandardNormal) {
  PixelNoise rng(7);
  double sum = 0, squares = 0, fourth = 0;
  int within_one = 0, within_two = 0;
  for (int i = 0; i < kDraws; ++i) {
    float g, u;
    rng.draw(g, u);
    sum += g;
    squares += g * g;
    fourth += double(g) * g * g * g;
    within_one += std::fabs(g) < 1.0f;
    within_two += std::fabs(g) < 2.0f;
  }
  EXPECT_NEAR(sum / kDraws, 0.0, 0.005);
  EXPECT_NEAR(squares / kDraws, 1.0, 0.01);
  EXPECT_NEAR(fourth / kDraws, 3.0, 0.06);  // a normal's kurtosis, not a uniform sum's
  EXPECT_NEAR(double(within_one) / kDraws, 0.6827, 0.002);
  EXPECT_NEAR(double(within_two) / kDraws, 0.9545, 0.001);
}

TEST(PixelNoise, UniformCoversZeroToOne) {
  PixelNoise rng(8);
  std::vector<int> tenths(10, 0);
  for (int i = 0; i < kDraws; ++i) {
    float g, u;
    rng.draw(g, u);
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    ++tenths[static_cast<int>(u * 10)];
  }
  for (int count : tenths) EXPECT_NEAR(count, kDraws / 10, kDraws / 200);
}

TEST(PixelNoise, SameSeedSameNumbersOtherSeedOthers) {
  PixelNoise a(3), b(3), c(4);
  int differ = 0;
  for (int i = 0; i < 1000; ++i) {
    float ga, ua, gb, ub, gc, uc;
    a.draw(ga, ua);
    b.draw(gb, ub);
    c.draw(gc, uc);
    ASSERT_EQ(ga, gb);
    ASSERT_EQ(ua, ub);
    differ += ga != gc;
  }
  EXPECT_GT(differ, 900);
}

// A flat frame: every pixel of the depth buffer at the value for z metres.
struct FlatFrame {
  Intrinsics k;
  std::vector<uint8_t> rgb;
  std::vector<float> buffer;
  double near = 0.01, far = 50.0;
  std::vector<uint8_t> image;
  std::vector<uint16_t> depth_mm;

  explicit FlatFrame(double z) {
    k.width = 320;
    k.height = 240;
    rgb.assign(k.width * k.height * 3, 100);
    const float b = static_cast<float>((far - near * far / z) / (far - near));  // linearDepth's inverse
    buffer.assign(k.width * k.height, b);
  }

  // mean and standard deviation (mm) of the pixels with a return, and their share
  void build(const DepthNoise& noise, double& mean, double& sd, double& returned) {
    PixelNoise rng(11);
    buildFrame(k, rgb.data(), buffer.data(), near, far, noise, rng, image, depth_mm, nullptr);
    double sum = 0, squares = 0;
    int n = 0;
    for (uint16_t mm : depth_mm) {
      if (mm == 0) continue;
      sum += mm;
      squares += double(mm) * mm;
      ++n;
    }
    mean = n ? sum / n : 0;
    sd = n ? std::sqrt(squares / n - mean * mean) : 0;
    returned = double(n) / depth_mm.size();
  }
};

TEST(BuildFrame, DepthNoiseHasTheKinectSigma) {
  for (double z : {1.0, 2.5, 4.0}) {
    FlatFrame frame(z);
    double mean, sd, returned;
    frame.build(DepthNoise(), mean, sd, returned);
    EXPECT_NEAR(mean, z * 1000, 0.5) << z;
    EXPECT_NEAR(sd, kinectSigma(z) * 1000, 0.05 * kinectSigma(z) * 1000 + 0.3) << z;
    EXPECT_EQ(returned, 1.0) << z;
  }
}

TEST(BuildFrame, NoNoiseIsExactAndDropoutDropsItsShare) {
  FlatFrame frame(2.0);
  DepthNoise exact;
  exact.scale = 0.0;
  double mean, sd, returned;
  frame.build(exact, mean, sd, returned);
  EXPECT_EQ(mean, 2000.0);
  EXPECT_EQ(sd, 0.0);

  DepthNoise dropping;
  dropping.dropout = 0.2;
  frame.build(dropping, mean, sd, returned);
  EXPECT_NEAR(returned, 0.8, 0.01);
}

TEST(BuildFrame, OutOfRangeHasNoReturn) {
  FlatFrame frame(9.0);  // beyond max_range 8 m
  double mean, sd, returned;
  frame.build(DepthNoise(), mean, sd, returned);
  EXPECT_EQ(returned, 0.0);
}

}  // namespace
}  // namespace rason_sim

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
