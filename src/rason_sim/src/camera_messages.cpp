#include "rason_sim/camera_messages.h"

#include <cstring>

namespace rason_sim {

void describeImage(const Intrinsics& k, const std_msgs::Header& header, sensor_msgs::Image& image) {
  image.header = header;
  image.width = k.width;
  image.height = k.height;
  image.encoding = "rgb8";
  image.step = k.width * 3;
}

sensor_msgs::Image depthImage(const Intrinsics& k, const std_msgs::Header& header,
                              const std::vector<uint16_t>& depth_mm) {
  sensor_msgs::Image depth;
  depth.header = header;
  depth.width = k.width;
  depth.height = k.height;
  depth.encoding = "16UC1";
  depth.is_bigendian = 0;
  depth.step = k.width * 2;
  depth.data.resize(depth_mm.size() * 2);
  std::memcpy(depth.data.data(), depth_mm.data(), depth.data.size());  // x86: little-endian
  return depth;
}

void describeCloud(const Intrinsics& k, const std_msgs::Header& header, sensor_msgs::PointCloud2& cloud) {
  cloud.header = header;
  cloud.width = k.width;
  cloud.height = k.height;
  cloud.is_dense = false;
  cloud.is_bigendian = false;
  cloud.point_step = kPointStep;
  cloud.row_step = kPointStep * k.width;
  const char* names[] = {"x", "y", "z", "rgb"};
  for (int i = 0; i < 4; ++i) {
    sensor_msgs::PointField f;
    f.name = names[i];
    f.offset = 4 * i;
    f.datatype = sensor_msgs::PointField::FLOAT32;
    f.count = 1;
    cloud.fields.push_back(f);
  }
}

sensor_msgs::CameraInfo cameraInfo(const Intrinsics& k, const std_msgs::Header& header) {
  sensor_msgs::CameraInfo info;
  info.header = header;
  info.width = k.width;
  info.height = k.height;
  info.distortion_model = "plumb_bob";
  info.D.assign(5, 0.0);
  info.K = {k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {k.fx, 0, k.cx, 0, 0, k.fy, k.cy, 0, 0, 0, 1, 0};
  return info;
}

}  // namespace rason_sim
