#include "rason_sim/params.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include "rason_sim/pacing.h"

namespace rason_sim {

using XmlRpc::XmlRpcValue;

double number(const XmlRpcValue& v, const std::string& what) {
  if (v.getType() == XmlRpcValue::TypeDouble) return static_cast<double>(v);
  if (v.getType() == XmlRpcValue::TypeInt) return static_cast<int>(v);
  throw std::invalid_argument(what + " must be a number");
}

double field(XmlRpcValue& s, const char* key, double fallback, const std::string& what) {
  if (s.getType() != XmlRpcValue::TypeStruct || !s.hasMember(key)) return fallback;
  return number(s[key], what + "/" + key);
}

bool flag(XmlRpcValue& s, const char* key, bool fallback) {
  if (s.getType() != XmlRpcValue::TypeStruct || !s.hasMember(key)) return fallback;
  if (s[key].getType() != XmlRpcValue::TypeBoolean)
    throw std::invalid_argument(std::string(key) + " must be true or false");
  return static_cast<bool>(s[key]);
}

double ParamReader::numberOr(const std::string& key, double fallback) const {
  XmlRpcValue v;
  if (!get(key, v)) return fallback;
  if (v.getType() == XmlRpcValue::TypeInt) return static_cast<int>(v);
  if (v.getType() == XmlRpcValue::TypeDouble) return static_cast<double>(v);
  return fallback;
}

int ParamReader::integerOr(const std::string& key, int fallback) const {
  XmlRpcValue v;
  if (!get(key, v)) return fallback;
  if (v.getType() == XmlRpcValue::TypeInt) return static_cast<int>(v);
  if (v.getType() != XmlRpcValue::TypeDouble) return fallback;
  const double d = static_cast<double>(v);
  return static_cast<int>(std::fmod(d, 1.0) < 0.5 ? std::floor(d) : std::ceil(d));  // roscpp's rounding
}

bool ParamReader::flagOr(const std::string& key, bool fallback) const {
  XmlRpcValue v;
  if (!get(key, v) || v.getType() != XmlRpcValue::TypeBoolean) return fallback;
  return static_cast<bool>(v);
}

std::string ParamReader::textOr(const std::string& key, const std::string& fallback) const {
  XmlRpcValue v;
  if (!get(key, v) || v.getType() != XmlRpcValue::TypeString) return fallback;
  return static_cast<std::string>(v);
}

bool ParamReader::names(const std::string& key, std::vector<std::string>& out) const {
  XmlRpcValue v;
  if (!get(key, v) || v.getType() != XmlRpcValue::TypeArray) return false;
  std::vector<std::string> names;
  for (int i = 0; i < v.size(); ++i) {
    if (v[i].getType() != XmlRpcValue::TypeString) return false;
    names.push_back(static_cast<std::string>(v[i]));
  }
  out = names;
  return true;
}

XmlRpcValue ParamReader::dictionary(const std::string& key) const {
  XmlRpcValue value;
  if (get(key, value) && value.getType() != XmlRpcValue::TypeStruct)
    throw std::invalid_argument("~" + key + " must be a dictionary");
  return value;
}

namespace {

Rgb rgbOf(XmlRpcValue& v, const std::string& name) {
  const std::string what = "~marker_colors/" + name;
  if (v.getType() != XmlRpcValue::TypeArray || v.size() != 3)
    throw std::invalid_argument(what + " must be [r, g, b] (0..1)");
  return Rgb{number(v[0], what), number(v[1], what), number(v[2], what)};
}

// A robot's cylinders: markers: {left: colour, right: colour, back: colour} gives each one
// named its colour and puts it on; left_marker, right_marker, back_marker (true or false)
// put one on or off whatever markers says.
void readMarkers(XmlRpcValue& s, RobotConfig& robot) {
  std::map<std::string, std::string> named;
  if (s.getType() == XmlRpcValue::TypeStruct && s.hasMember("markers")) {
    XmlRpcValue& markers = s["markers"];
    if (markers.getType() != XmlRpcValue::TypeStruct)
      throw std::invalid_argument("~" + robot.name + "/markers must be {left: colour, right: colour, back: colour}");
    for (auto& entry : markers) {
      if (entry.first != "left" && entry.first != "right" && entry.first != "back")
        throw std::invalid_argument("~" + robot.name + "/markers: " + entry.first +
                                    " is not left, right or back");
      if (entry.second.getType() != XmlRpcValue::TypeString)
        throw std::invalid_argument("~" + robot.name + "/markers/" + entry.first + " must name a colour");
      named[entry.first] = static_cast<std::string>(entry.second);
    }
  }
  struct Side {
    const char* name;
    bool& on;
    std::string& colour;
  };
  for (const Side& side : {Side{"left", robot.left_marker, robot.left_color},
                           Side{"right", robot.right_marker, robot.right_color},
                           Side{"back", robot.back_marker, robot.back_color}}) {
    const auto colour = named.find(side.name);
    if (colour != named.end()) side.colour = colour->second;
    side.on = flag(s, (std::string(side.name) + "_marker").c_str(), colour != named.end());
  }
}

}  // namespace

WorldConfig worldFromParams(const ParamReader& params) {
  WorldConfig world;
  XmlRpcValue room = params.dictionary("room");
  world.room_x = field(room, "size_x", world.room_x, "~room");
  world.room_y = field(room, "size_y", world.room_y, "~room");
  world.wall_height = field(room, "wall_height", world.wall_height, "~room");
  world.ambient = params.numberOr("ambient", world.ambient);
  world.brightness = params.numberOr("brightness", world.brightness);
  world.timestep = params.numberOr("timestep", world.timestep);

  XmlRpcValue lights;
  if (params.get("lights", lights)) {
    if (lights.getType() != XmlRpcValue::TypeArray)
      throw std::invalid_argument("~lights must be a list of {x, y, z, intensity}");
    for (int i = 0; i < lights.size(); ++i) {
      LightConfig light;
      light.x = field(lights[i], "x", light.x, "~lights");
      light.y = field(lights[i], "y", light.y, "~lights");
      light.z = field(lights[i], "z", light.z, "~lights");
      light.intensity = field(lights[i], "intensity", light.intensity, "~lights");
      world.lights.push_back(light);
    }
  } else {
    world.lights.push_back(LightConfig());
  }

  XmlRpcValue boxes;
  if (params.get("boxes", boxes)) {
    if (boxes.getType() != XmlRpcValue::TypeArray)
      throw std::invalid_argument("~boxes must be a list of {x, y, z, size_x, size_y, size_z, yaw}");
    for (int i = 0; i < boxes.size(); ++i) {
      BoxConfig box;
      box.x = field(boxes[i], "x", box.x, "~boxes");
      box.y = field(boxes[i], "y", box.y, "~boxes");
      box.z = field(boxes[i], "z", box.z, "~boxes");
      box.size_x = field(boxes[i], "size_x", box.size_x, "~boxes");
      box.size_y = field(boxes[i], "size_y", box.size_y, "~boxes");
      box.size_z = field(boxes[i], "size_z", box.size_z, "~boxes");
      box.yaw = field(boxes[i], "yaw", box.yaw, "~boxes");
      world.boxes.push_back(box);
    }
  }

  XmlRpcValue colors = params.dictionary("marker_colors");
  if (colors.getType() == XmlRpcValue::TypeStruct)
    for (auto& entry : colors) world.marker_colors[entry.first] = rgbOf(entry.second, entry.first);

  XmlRpcValue camera = params.dictionary("camera");
  world.camera.width = static_cast<int>(field(camera, "width", world.camera.width, "~camera"));
  world.camera.height = static_cast<int>(field(camera, "height", world.camera.height, "~camera"));
  world.camera.horizontal_fov_deg = field(camera, "hfov", world.camera.horizontal_fov_deg, "~camera");
  world.camera.height_m = field(camera, "height_m", world.camera.height_m, "~camera");

  std::vector<std::string> names;
  if (!params.names("robots", names)) throw std::invalid_argument("~robots (list of names) is not set");
  for (const std::string& name : names) {
    RobotConfig robot;
    robot.name = name;
    XmlRpcValue s = params.dictionary(name);
    robot.start.x = field(s, "x", 0.0, "~" + name);
    robot.start.y = field(s, "y", 0.0, "~" + name);
    robot.start.yaw = field(s, "yaw", 0.0, "~" + name);
    robot.camera = flag(s, "camera", false);
    readMarkers(s, robot);
    robot.slip.left = field(s, "left_slip", 0.0, "~" + name);
    robot.slip.right = field(s, "right_slip", 0.0, "~" + name);
    world.robots.push_back(robot);
  }
  validate(world);
  return world;
}

SimParams simParamsFrom(const ParamReader& params) {
  SimParams p;
  p.world = worldFromParams(params);
  p.real_time_factor = params.numberOr("real_time_factor", p.real_time_factor);
  p.odom_rate = params.numberOr("odom_rate", p.odom_rate);
  p.camera_rate = params.numberOr("camera_rate", p.camera_rate);
  p.clock_rate = params.numberOr("clock_rate", p.clock_rate);
  p.cmd_vel_timeout = params.numberOr("cmd_vel_timeout", p.cmd_vel_timeout);
  p.max_sim_time = params.numberOr("max_sim_time", p.max_sim_time);
  p.lockstep = params.flagOr("lockstep", p.real_time_factor == 0.0);
  p.frame_ack_topic = params.textOr("frame_ack_topic", p.frame_ack_topic);
  p.frame_ack_timeout = params.numberOr("frame_ack_timeout", p.frame_ack_timeout);
  p.max_lockstep_factor = params.numberOr("max_lockstep_factor", p.max_lockstep_factor);
  p.control_ack_topic = params.textOr("control_ack_topic", p.control_ack_topic);
  p.odom_ack_topic = params.textOr("odom_ack_topic", p.odom_ack_topic);
  p.control_rate = params.numberOr("control_rate", p.control_rate);
  p.control_ack_timeout = params.numberOr("control_ack_timeout", p.control_ack_timeout);
  p.seed = params.integerOr("seed", p.seed);
  XmlRpcValue camera = params.dictionary("camera");
  p.noise.scale = field(camera, "depth_noise", 1.0, "~camera");
  p.noise.dropout = field(camera, "depth_dropout", 0.0, "~camera");
  p.noise.min_range = p.world.camera.min_range;
  p.noise.max_range = p.world.camera.max_range;

  if (p.real_time_factor < 0.0 || p.odom_rate <= 0.0 || p.camera_rate <= 0.0 || p.clock_rate <= 0.0)
    throw std::invalid_argument("rates must be > 0 and real_time_factor >= 0");
  if (!(p.frame_ack_timeout > 0.0 && p.frame_ack_timeout < 3600.0))
    throw std::invalid_argument("~frame_ack_timeout must be in (0, 3600) s");
  if (!(p.max_lockstep_factor >= LockstepPace::kMinFactor && p.max_lockstep_factor <= 1000.0))
    throw std::invalid_argument("~max_lockstep_factor must be in [0.2, 1000]");
  if (!(p.control_rate > 0.0 && p.control_rate <= 1000.0))
    throw std::invalid_argument("~control_rate must be in (0, 1000] Hz");
  if (!(p.control_ack_timeout > 0.0 && p.control_ack_timeout < 3600.0))
    throw std::invalid_argument("~control_ack_timeout must be in (0, 3600) s");
  if (p.noise.dropout < 0.0 || p.noise.dropout >= 1.0)
    throw std::invalid_argument("~camera/depth_dropout must be in [0, 1)");
  return p;
}

}  // namespace rason_sim
