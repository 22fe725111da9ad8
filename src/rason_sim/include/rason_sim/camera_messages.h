// The camera's messages as freenect publishes them, around what buildFrame (depth_camera.h)
// made of a rendered frame. Message building only: nothing here needs a ROS master.
#pragma once

#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>

#include <cstdint>
#include <vector>

#include "rason_sim/depth_camera.h"

namespace rason_sim {

// image.data holds buildFrame's rgb8 image; sets the rest.
void describeImage(const Intrinsics& k, const std_msgs::Header& header, sensor_msgs::Image& image);

// REP 118: 16UC1 in millimetres, 0 = no return (buildFrame's depth_mm).
sensor_msgs::Image depthImage(const Intrinsics& k, const std_msgs::Header& header,
                              const std::vector<uint16_t>& depth_mm);

// cloud.data holds buildFrame's organized cloud; sets the rest (fields x, y, z, rgb: float32).
void describeCloud(const Intrinsics& k, const std_msgs::Header& header, sensor_msgs::PointCloud2& cloud);

// a pinhole camera without distortion
sensor_msgs::CameraInfo cameraInfo(const Intrinsics& k, const std_msgs::Header& header);

}  // namespace rason_sim
