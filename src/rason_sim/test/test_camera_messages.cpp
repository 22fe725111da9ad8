// The camera's messages around a frame: sizes, encodings, the depth's byte order, the cloud's
// fields and the pinhole intrinsics, as freenect publishes them. No master.
#include <gtest/gtest.h>

#include "rason_sim/camera_messages.h"

namespace rason_sim {
namespace {

Intrinsics smallCamera() {
  Intrinsics k;
  k.width = 4;
  k.height = 3;
  k.fx = 5.0;
  k.fy = 6.0;
  k.cx = 1.5;
  k.cy = 1.0;
  return k;
}

std_msgs::Header opticalHeader() {
  std_msgs::Header header;
  header.stamp = ros::Time(12.5);
  header.frame_id = "helper/camera_rgb_optical_frame";
  return header;
}

TEST(CameraMessages, TheImageIsRgb8WithThreeBytesAPixel) {
  sensor_msgs::Image image;
  image.data.assign(4 * 3 * 3, 7);
  describeImage(smallCamera(), opticalHeader(), image);
  EXPECT_EQ(image.header.frame_id, "helper/camera_rgb_optical_frame");
  EXPECT_EQ(image.header.stamp, ros::Time(12.5));
  EXPECT_EQ(image.width, 4u);
  EXPECT_EQ(image.height, 3u);
  EXPECT_EQ(image.encoding, "rgb8");
  EXPECT_EQ(image.step, 12u);
  EXPECT_EQ(image.data.size(), image.step * image.height);
}

TEST(CameraMessages, TheDepthIsLittleEndianMillimetres) {
  std::vector<uint16_t> depth_mm(12, 0);
  depth_mm[0] = 1234;    // 0x04d2
  depth_mm[11] = 8000;   // 0x1f40
  const sensor_msgs::Image depth = depthImage(smallCamera(), opticalHeader(), depth_mm);
  EXPECT_EQ(depth.encoding, "16UC1");
  EXPECT_EQ(depth.is_bigendian, 0);
  EXPECT_EQ(depth.step, 8u);
  ASSERT_EQ(depth.data.size(), 24u);
  EXPECT_EQ(depth.data[0], 0xd2);
  EXPECT_EQ(depth.data[1], 0x04);
  EXPECT_EQ(depth.data[22], 0x40);
  EXPECT_EQ(depth.data[23], 0x1f);
  EXPECT_EQ(depth.data[2], 0);  // no return
  EXPECT_EQ(depth.header.frame_id, "helper/camera_rgb_optical_frame");
}

TEST(CameraMessages, TheCloudIsOrganizedWithFourFloatFields) {
  sensor_msgs::PointCloud2 cloud;
  describeCloud(smallCamera(), opticalHeader(), cloud);
  EXPECT_EQ(cloud.width, 4u);
  EXPECT_EQ(cloud.height, 3u);  // organized: one row per image row
  EXPECT_FALSE(cloud.is_dense);  // NaN where there is no return
  EXPECT_EQ(cloud.point_step, static_cast<uint32_t>(kPointStep));
  EXPECT_EQ(cloud.row_step, static_cast<uint32_t>(kPointStep * 4));
  ASSERT_EQ(cloud.fields.size(), 4u);
  const char* names[] = {"x", "y", "z", "rgb"};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(cloud.fields[i].name, names[i]);
    EXPECT_EQ(cloud.fields[i].offset, 4u * i);
    EXPECT_EQ(cloud.fields[i].datatype, sensor_msgs::PointField::FLOAT32);
    EXPECT_EQ(cloud.fields[i].count, 1u);
  }
}

TEST(CameraMessages, TheCameraInfoIsAnUndistortedPinhole) {
  const sensor_msgs::CameraInfo info = cameraInfo(smallCamera(), opticalHeader());
  EXPECT_EQ(info.width, 4u);
  EXPECT_EQ(info.height, 3u);
  EXPECT_EQ(info.distortion_model, "plumb_bob");
  EXPECT_EQ(info.D, std::vector<double>(5, 0.0));
  const boost::array<double, 9> K = {5.0, 0, 1.5, 0, 6.0, 1.0, 0, 0, 1};
  EXPECT_EQ(info.K, K);
  const boost::array<double, 12> P = {5.0, 0, 1.5, 0, 0, 6.0, 1.0, 0, 0, 0, 1, 0};
  EXPECT_EQ(info.P, P);
  const boost::array<double, 9> R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_EQ(info.R, R);
}

}  // namespace
}  // namespace rason_sim

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
