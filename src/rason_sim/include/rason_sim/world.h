// World description of the simulator and its translation into MuJoCo's MJCF.
// Kept free of ROS so the same description can be built from parameters or in tests.
#pragma once

#include <string>
#include <vector>

#include "rason_sim/markers.h"

namespace rason_sim {

// Kobuki-like base geometry (metres), from the Kobuki datasheet.
struct BaseGeometry {
  double radius = 0.177;
  double wheel_radius = 0.035;
  double wheel_separation = 0.230;
};

struct Pose2D {
  double x = 0.0, y = 0.0, yaw = 0.0;  // metres, radians (counter-clockwise from +x)
};

// The share of each wheel's rotation that does not move the robot over the floor (0: none;
// a few per cent on a real floor), so odometry overestimates the robot's travel.
struct WheelSlip {
  double left = 0.0, right = 0.0;
};

struct RobotConfig {
  std::string name;             // also the ROS namespace and tf prefix
  Pose2D start;
  bool camera = false;          // Kinect-like RGB-D camera
  bool left_marker = false;     // a cylinder on the robot's left
  bool right_marker = false;    // a cylinder on the robot's right
  bool back_marker = false;     // a cylinder behind the middle of the two (thesis §8.1)
  // their colours, names in WorldConfig::marker_colors (the case study's by default)
  std::string left_color = "green", right_color = "orange", back_color = "blue";
  WheelSlip slip;
};

struct LightConfig {
  double x = 0.0, y = 0.0, z = 2.8;
  double intensity = 0.7;       // diffuse, 0..1
};

struct BoxConfig {              // static obstacle, e.g. to hide a marker
  double x = 0.0, y = 0.0, z = 0.25;
  double size_x = 0.1, size_y = 0.1, size_z = 0.5;  // full sizes
  double yaw = 0.0;
};

struct CameraConfig {
  int width = 640;
  int height = 480;
  double horizontal_fov_deg = 57.0;   // Kinect
  double height_m = 0.30;             // above the floor
  double forward_m = 0.08;            // ahead of the base centre
  double min_range = 0.45;            // Kinect returns no depth closer than this
  double max_range = 8.0;
};

struct WorldConfig {
  double room_x = 8.0, room_y = 8.0, wall_height = 1.0;
  double ambient = 0.25;              // global ambient light, 0..1
  double brightness = 1.0;            // scales every light (1 = as configured)
  double timestep = 0.002;            // physics step (s)
  std::vector<LightConfig> lights;
  std::vector<RobotConfig> robots;
  std::vector<BoxConfig> boxes;
  MarkerPalette marker_colors = defaultMarkerPalette();
  BaseGeometry base;
  CameraConfig camera;
};

// Marker (cylinder) geometry: centres 22.7 cm apart, across the robot's axle.
constexpr double kMarkerSeparation = 0.227;
constexpr double kMarkerRadius = 0.02;
constexpr double kMarkerBottom = 0.12;
constexpr double kMarkerTop = 0.45;
// The third cylinder: behind the middle of the other two, so the three are not in a line
// and at least two are in view from any direction.
constexpr double kBackMarkerOffset = 0.12;

// Vertical field of view MuJoCo needs for a horizontal one at the given image size.
double verticalFovDeg(const CameraConfig& camera);

// Names the MJCF uses, so the node can look up ids.
std::string rootJointName(const std::string& robot);
std::string wheelJointName(const std::string& robot, bool left);
std::string wheelActuatorName(const std::string& robot, bool left);
std::string cameraName(const std::string& robot);

// Throws std::invalid_argument on an inconsistent world (duplicate names, a marker colour
// not in the palette, ...).
void validate(const WorldConfig& world);
std::string buildMjcf(const WorldConfig& world);

}  // namespace rason_sim
