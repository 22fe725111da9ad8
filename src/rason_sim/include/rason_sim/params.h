// The simulator's private parameters (README.md, "Parameters"): read with roscpp's
// conversions, checked, and turned into the world and the node's settings. No ROS master
// here: parameters come through a lookup, the node's private NodeHandle or a dictionary in
// tests. A bad parameter throws std::invalid_argument saying what is wrong.
#pragma once

#include <xmlrpcpp/XmlRpcValue.h>

#include <functional>
#include <string>
#include <vector>

#include "rason_sim/depth_camera.h"
#include "rason_sim/world.h"

namespace rason_sim {

// Fills value with the parameter key (relative to the node's private namespace); false when
// it is not set.
using ParamLookup = std::function<bool(const std::string& key, XmlRpc::XmlRpcValue& value)>;

// A value inside a dictionary or list parameter: an int or a double, else throws
// "<what> must be a number".
double number(const XmlRpc::XmlRpcValue& value, const std::string& what);
// s[key] as number(); fallback when s is no dictionary or has no key.
double field(XmlRpc::XmlRpcValue& s, const char* key, double fallback, const std::string& what);
// s[key] as a boolean; fallback when s is no dictionary or has no key.
bool flag(XmlRpc::XmlRpcValue& s, const char* key, bool fallback);

// Top-level parameters as roscpp's NodeHandle::param reads them: a value of another type
// counts as unset, so the fallback is taken (a double accepts an int; an int accepts a
// double, rounded as roscpp rounds it).
class ParamReader {
 public:
  explicit ParamReader(ParamLookup lookup) : lookup_(std::move(lookup)) {}

  bool get(const std::string& key, XmlRpc::XmlRpcValue& value) const { return lookup_(key, value); }
  double numberOr(const std::string& key, double fallback) const;
  int integerOr(const std::string& key, int fallback) const;
  bool flagOr(const std::string& key, bool fallback) const;
  std::string textOr(const std::string& key, const std::string& fallback) const;
  // a list of strings; false when unset or not such a list
  bool names(const std::string& key, std::vector<std::string>& out) const;
  // unset: an empty (invalid) value; set to anything but a dictionary: throws
  XmlRpc::XmlRpcValue dictionary(const std::string& key) const;

 private:
  ParamLookup lookup_;
};

// ~room, ~ambient, ~brightness, ~timestep, ~lights, ~boxes, ~camera, ~robots and each robot's
// dictionary; validate()d.
WorldConfig worldFromParams(const ParamReader& params);

// Everything the node reads, with its default.
struct SimParams {
  WorldConfig world;
  double real_time_factor = 1.0, odom_rate = 50.0, camera_rate = 10.0, clock_rate = 100.0;
  double cmd_vel_timeout = 0.6, max_sim_time = 0.0;
  bool lockstep = false;  // default: real_time_factor == 0
  std::string frame_ack_topic = "robots_seen";
  double frame_ack_timeout = 2.0;
  double max_lockstep_factor = 2.5;
  std::string control_ack_topic = "odom_commanded";  // a controller's tick reports; empty: none
  std::string odom_ack_topic = "odom_filtered";      // the odometry relayed to the controller
  double control_rate = 50.0;                        // Hz of those ticks (motion_decomp's ~rate)
  double control_ack_timeout = 0.5;
  int seed = 1;
  DepthNoise noise;  // ~camera/depth_noise, depth_dropout; the camera's range
};

SimParams simParamsFrom(const ParamReader& params);

}  // namespace rason_sim
