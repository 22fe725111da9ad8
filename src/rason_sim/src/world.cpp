#include "rason_sim/world.h"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rason_sim {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kWallThickness = 0.1;

std::string rgb(double grey) {
  std::ostringstream out;
  out << grey << ' ' << grey << ' ' << grey;
  return out.str();
}

void writeRobot(std::ostringstream& xml, const RobotConfig& robot, const WorldConfig& world) {
  const BaseGeometry& base = world.base;
  const std::string& n = robot.name;
  const double half_track = base.wheel_separation / 2.0;
  xml << "    <body name='" << n << "' pos='" << robot.start.x << ' ' << robot.start.y
      << " 0' euler='0 0 " << robot.start.yaw << "'>\n"
      << "      <freejoint name='" << rootJointName(n) << "'/>\n"
      // Kobuki: 2.35 kg; the TurtleBot plates and laptop add to it.
      << "      <geom name='" << n << "_base' type='cylinder' size='" << base.radius
      << " 0.045' pos='0 0 0.065' mass='4.0' material='base'/>\n"
      << "      <geom name='" << n << "_plate' type='cylinder' size='" << base.radius - 0.01
      << " 0.004' pos='0 0 0.11' mass='0.2' material='plate' contype='0' conaffinity='0'/>\n";
  for (bool left : {true, false}) {
    const double side = left ? 1.0 : -1.0;
    xml << "      <body name='" << n << (left ? "_left" : "_right") << "_wheel' pos='0 "
        << side * half_track << ' ' << base.wheel_radius << "'>\n"
        << "        <joint name='" << wheelJointName(n, left)
        << "' type='hinge' axis='0 1 0' armature='0.0005' damping='0.0005'/>\n"
        << "        <geom type='cylinder' size='" << base.wheel_radius
        << " 0.01' euler='1.5708 0 0' mass='0.15' material='wheel' friction='1.2 0.005 0.0001'/>\n"
        << "      </body>\n";
  }
  // Frictionless casters (priority wins over the floor's friction), or the base crawls.
  for (double x : {0.12, -0.12}) {
    xml << "      <geom type='sphere' size='0.015' pos='" << x
        << " 0 0.015' mass='0.05' priority='1' condim='1' friction='0 0 0' material='wheel'/>\n";
  }
  const double marker_z = (kMarkerBottom + kMarkerTop) / 2.0;
  const double marker_half = (kMarkerTop - kMarkerBottom) / 2.0;
  struct Cylinder {
    bool on;
    const char* side;
    const std::string& colour;
    double x, y;
  };
  for (const Cylinder& c : {Cylinder{robot.left_marker, "left", robot.left_color, 0.0, kMarkerSeparation / 2.0},
                            Cylinder{robot.right_marker, "right", robot.right_color, 0.0, -kMarkerSeparation / 2.0},
                            Cylinder{robot.back_marker, "back", robot.back_color, -kBackMarkerOffset, 0.0}}) {
    if (!c.on) continue;
    xml << "      <geom name='" << n << '_' << c.side << "_marker' type='cylinder' size='"
        << kMarkerRadius << ' ' << marker_half << "' pos='" << c.x << ' ' << c.y << ' ' << marker_z
        << "' mass='0.02' material='" << markerMaterial(c.colour) << "' contype='0' conaffinity='0'/>\n";
  }
  if (robot.camera) {
    const CameraConfig& cam = world.camera;
    // A MuJoCo camera looks along its -z with +x to the image's right: image right is the
    // robot's -y, image up the robot's +z.
    xml << "      <camera name='" << cameraName(n) << "' pos='" << cam.forward_m << " 0 "
        << cam.height_m << "' xyaxes='0 -1 0 0 0 1' fovy='" << verticalFovDeg(cam) << "'/>\n"
        << "      <geom type='box' size='0.03 0.14 0.02' pos='" << cam.forward_m - 0.035
        << " 0 " << cam.height_m << "' mass='0.3' material='wheel' contype='0' conaffinity='0'/>\n";
  }
  xml << "    </body>\n";
}

}  // namespace

double verticalFovDeg(const CameraConfig& camera) {
  const double half_h = camera.horizontal_fov_deg * kPi / 360.0;
  const double focal = (camera.width / 2.0) / std::tan(half_h);
  return 2.0 * std::atan((camera.height / 2.0) / focal) * 180.0 / kPi;
}

std::string rootJointName(const std::string& robot) { return robot + "_root"; }
std::string wheelJointName(const std::string& robot, bool left) {
  return robot + (left ? "_left_wheel_joint" : "_right_wheel_joint");
}
std::string wheelActuatorName(const std::string& robot, bool left) {
  return robot + (left ? "_left_motor" : "_right_motor");
}
std::string cameraName(const std::string& robot) { return robot + "_camera"; }

void validate(const WorldConfig& world) {
  if (world.robots.empty()) throw std::invalid_argument("the world has no robots");
  std::set<std::string> names;
  for (const RobotConfig& robot : world.robots) {
    if (robot.name.empty() || robot.name.find_first_not_of(
            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos)
      throw std::invalid_argument("robot name '" + robot.name +
                                  "' must be a non-empty ROS name (letters, digits, _)");
    if (!names.insert(robot.name).second)
      throw std::invalid_argument("two robots are named '" + robot.name + "'");
    if (std::fabs(robot.start.x) > world.room_x / 2 || std::fabs(robot.start.y) > world.room_y / 2)
      throw std::invalid_argument("robot '" + robot.name + "' starts outside the room");
    for (double slip : {robot.slip.left, robot.slip.right})
      if (!(slip >= 0.0 && slip < 0.5))
        throw std::invalid_argument("robot '" + robot.name + "': wheel slip must be in [0, 0.5)");
  }
  validatePalette(world.marker_colors);
  for (const RobotConfig& robot : world.robots)
    for (const std::string* colour : {&robot.left_color, &robot.right_color, &robot.back_color})
      if (!world.marker_colors.count(*colour))
        throw std::invalid_argument("robot '" + robot.name + "': marker colour '" + *colour +
                                    "' is not in ~marker_colors");
  // Two bases started inside each other would be thrown apart by the contact solver.
  for (size_t i = 0; i < world.robots.size(); ++i)
    for (size_t j = i + 1; j < world.robots.size(); ++j) {
      const Pose2D& a = world.robots[i].start;
      const Pose2D& b = world.robots[j].start;
      if (std::hypot(a.x - b.x, a.y - b.y) < 2.0 * world.base.radius)
        throw std::invalid_argument("robots '" + world.robots[i].name + "' and '" +
                                    world.robots[j].name + "' start overlapping");
    }
  if (world.room_x <= 1.0 || world.room_y <= 1.0) throw std::invalid_argument("room too small");
  if (world.timestep <= 0.0 || world.timestep > 0.01)
    throw std::invalid_argument("timestep must be in (0, 0.01] s");
  if (world.camera.width <= 0 || world.camera.height <= 0 ||
      world.camera.horizontal_fov_deg <= 0.0 || world.camera.horizontal_fov_deg >= 170.0)
    throw std::invalid_argument("bad camera size or field of view");
  if (world.brightness < 0.0) throw std::invalid_argument("brightness must be >= 0");
}

std::string buildMjcf(const WorldConfig& world) {
  validate(world);
  std::ostringstream xml;
  xml.precision(6);
  const double b = world.brightness;
  xml << "<mujoco model='rason_world'>\n"
      << "  <compiler angle='radian'/>\n"
      << "  <option timestep='" << world.timestep << "' integrator='Euler'/>\n"
      // extent fixes the depth range: near = znear*extent = 0.1 m, far = zfar*extent = 20 m.
      << "  <statistic extent='10' center='0 0 0.5'/>\n"
      << "  <visual>\n"
      << "    <global offwidth='" << world.camera.width << "' offheight='" << world.camera.height
      << "'/>\n"
      << "    <quality shadowsize='0' offsamples='0'/>\n"
      << "    <map znear='0.01' zfar='2'/>\n"
      << "    <headlight ambient='" << rgb(world.ambient * b) << "' diffuse='0 0 0' specular='0 0 0'/>\n"
      << "  </visual>\n"
      << "  <asset>\n"
      << "    <material name='floor' rgba='0.55 0.55 0.55 1' specular='0.05'/>\n"
      << "    <material name='wall' rgba='0.75 0.75 0.73 1' specular='0.05'/>\n"
      << "    <material name='base' rgba='0.18 0.18 0.2 1' specular='0.2'/>\n"
      << "    <material name='plate' rgba='0.35 0.3 0.25 1' specular='0.1'/>\n"
      << "    <material name='wheel' rgba='0.05 0.05 0.05 1' specular='0.1'/>\n"
      << "    <material name='obstacle' rgba='0.4 0.4 0.45 1' specular='0.05'/>\n"
      ;
  for (const auto& colour : world.marker_colors) {
    const Rgb& c = colour.second;
    xml << "    <material name='" << markerMaterial(colour.first) << "' rgba='" << c.r << ' ' << c.g
        << ' ' << c.b << " 1' specular='0.1'/>\n";
  }
  xml << "  </asset>\n"
      << "  <worldbody>\n";
  for (const LightConfig& light : world.lights) {
    xml << "    <light pos='" << light.x << ' ' << light.y << ' ' << light.z
        << "' dir='0 0 -1' directional='false' castshadow='false' cutoff='90' exponent='0'"
        << " diffuse='" << rgb(light.intensity * b) << "' specular='" << rgb(0.1 * b) << "'/>\n";
  }
  const double hx = world.room_x / 2.0, hy = world.room_y / 2.0, hz = world.wall_height / 2.0;
  xml << "    <geom name='floor' type='plane' size='" << hx << ' ' << hy
      << " 0.1' material='floor' friction='1 0.005 0.0001'/>\n";
  const double t = kWallThickness / 2.0;
  xml << "    <geom name='wall_north' type='box' size='" << hx + 2 * t << ' ' << t << ' ' << hz
      << "' pos='0 " << hy + t << ' ' << hz << "' material='wall'/>\n"
      << "    <geom name='wall_south' type='box' size='" << hx + 2 * t << ' ' << t << ' ' << hz
      << "' pos='0 " << -hy - t << ' ' << hz << "' material='wall'/>\n"
      << "    <geom name='wall_east' type='box' size='" << t << ' ' << hy << ' ' << hz << "' pos='"
      << hx + t << " 0 " << hz << "' material='wall'/>\n"
      << "    <geom name='wall_west' type='box' size='" << t << ' ' << hy << ' ' << hz << "' pos='"
      << -hx - t << " 0 " << hz << "' material='wall'/>\n";
  for (const BoxConfig& box : world.boxes) {
    xml << "    <geom type='box' size='" << box.size_x / 2 << ' ' << box.size_y / 2 << ' '
        << box.size_z / 2 << "' pos='" << box.x << ' ' << box.y << ' ' << box.z << "' euler='0 0 "
        << box.yaw << "' material='obstacle'/>\n";
  }
  for (const RobotConfig& robot : world.robots) writeRobot(xml, robot, world);
  xml << "  </worldbody>\n  <actuator>\n";
  for (const RobotConfig& robot : world.robots) {
    for (bool left : {true, false}) {
      // Velocity servo with a torque limit: accelerates like a Kobuki (~1 m/s^2) without
      // spinning the wheels on the floor.
      xml << "    <velocity name='" << wheelActuatorName(robot.name, left) << "' joint='"
          << wheelJointName(robot.name, left)
          << "' kv='0.08' forcelimited='true' forcerange='-0.12 0.12'/>\n";
    }
  }
  xml << "  </actuator>\n</mujoco>\n";
  return xml.str();
}

}  // namespace rason_sim
