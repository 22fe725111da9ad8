// The simulator's private parameters from XmlRpcValues, as the parameter server would hand
// them over: the defaults, roscpp's conversions, and what a bad parameter is told. No master.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "rason_sim/params.h"

namespace rason_sim {
namespace {

using XmlRpc::XmlRpcValue;

// A private namespace: a dictionary of parameters.
ParamReader readerOf(XmlRpcValue& params) {
  return ParamReader([&params](const std::string& key, XmlRpcValue& value) {
    if (params.getType() != XmlRpcValue::TypeStruct || !params.hasMember(key)) return false;
    value = params[key];
    return true;
  });
}

// The smallest world: one robot, everything else unset.
XmlRpcValue oneRobot() {
  XmlRpcValue params;
  params["robots"][0] = std::string("solo");
  return params;
}

// what simParamsFrom says of params, "" when it takes them
std::string errorOf(XmlRpcValue& params) {
  try {
    simParamsFrom(readerOf(params));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Params, UnsetParametersTakeTheDefaults) {
  XmlRpcValue params = oneRobot();
  const SimParams p = simParamsFrom(readerOf(params));
  EXPECT_EQ(p.real_time_factor, 1.0);
  EXPECT_EQ(p.odom_rate, 50.0);
  EXPECT_EQ(p.camera_rate, 10.0);
  EXPECT_EQ(p.clock_rate, 100.0);
  EXPECT_EQ(p.cmd_vel_timeout, 0.6);
  EXPECT_EQ(p.max_sim_time, 0.0);
  EXPECT_FALSE(p.lockstep);
  EXPECT_EQ(p.frame_ack_topic, "robots_seen");
  EXPECT_EQ(p.frame_ack_timeout, 2.0);
  EXPECT_EQ(p.max_lockstep_factor, 2.5);
  EXPECT_EQ(p.control_ack_topic, "odom_commanded");
  EXPECT_EQ(p.odom_ack_topic, "odom_filtered");
  EXPECT_EQ(p.control_rate, 50.0);
  EXPECT_EQ(p.control_ack_timeout, 0.5);
  EXPECT_EQ(p.seed, 1);
  EXPECT_EQ(p.noise.scale, 1.0);
  EXPECT_EQ(p.noise.dropout, 0.0);
  EXPECT_EQ(p.noise.min_range, p.world.camera.min_range);
  EXPECT_EQ(p.noise.max_range, p.world.camera.max_range);

  const WorldConfig defaults;
  EXPECT_EQ(p.world.room_x, defaults.room_x);
  EXPECT_EQ(p.world.timestep, defaults.timestep);
  ASSERT_EQ(p.world.lights.size(), 1u);  // one light over the middle
  EXPECT_EQ(p.world.lights[0].z, LightConfig().z);
  EXPECT_TRUE(p.world.boxes.empty());
  ASSERT_EQ(p.world.robots.size(), 1u);
  const RobotConfig& solo = p.world.robots[0];
  EXPECT_EQ(solo.name, "solo");
  EXPECT_EQ(solo.start.x, 0.0);
  EXPECT_FALSE(solo.camera || solo.left_marker || solo.right_marker || solo.back_marker);
  EXPECT_EQ(solo.slip.left, 0.0);
}

TEST(Params, LockstepIsTheDefaultAsFastAsPossible) {
  XmlRpcValue params = oneRobot();
  params["real_time_factor"] = 0;  // an int, as YAML writes 0
  EXPECT_TRUE(simParamsFrom(readerOf(params)).lockstep);
  params["lockstep"] = false;
  EXPECT_FALSE(simParamsFrom(readerOf(params)).lockstep);
}

TEST(Params, TopLevelValuesConvertAsRoscppDoes) {
  XmlRpcValue params = oneRobot();
  params["odom_rate"] = 20;                       // an int for a double
  params["camera_rate"] = std::string("fast");    // another type: as if unset
  params["lockstep"] = std::string("true");       // not a boolean: as if unset
  params["frame_ack_topic"] = 7;                  // not a string: as if unset
  params["control_ack_topic"] = std::string("");  // empty: no controller lockstep
  params["seed"] = 2.6;                           // rounded to the nearest
  const SimParams p = simParamsFrom(readerOf(params));
  EXPECT_EQ(p.odom_rate, 20.0);
  EXPECT_EQ(p.camera_rate, 10.0);
  EXPECT_FALSE(p.lockstep);
  EXPECT_EQ(p.frame_ack_topic, "robots_seen");
  EXPECT_EQ(p.control_ack_topic, "");
  EXPECT_EQ(p.seed, 3);
  params["seed"] = 2.4;
  EXPECT_EQ(simParamsFrom(readerOf(params)).seed, 2);
}

TEST(Params, TheWorldIsReadFromItsDictionariesAndLists) {
  XmlRpcValue params = oneRobot();
  params["robots"][1] = std::string("duo");
  params["room"]["size_x"] = 6;
  params["room"]["wall_height"] = 0.5;
  params["brightness"] = 0.3;
  params["lights"][0]["x"] = 1.0;
  params["lights"][1]["intensity"] = 0.2;
  params["boxes"][0]["size_z"] = 0.4;
  params["boxes"][0]["yaw"] = 1;
  params["camera"]["width"] = 320;
  params["camera"]["hfov"] = 60;
  params["camera"]["depth_noise"] = 0;
  params["camera"]["depth_dropout"] = 0.1;
  params["solo"]["x"] = -1.5;
  params["solo"]["camera"] = true;
  params["duo"]["y"] = 2;
  params["duo"]["left_marker"] = true;
  params["duo"]["back_marker"] = true;
  params["duo"]["right_slip"] = 0.05;
  const SimParams p = simParamsFrom(readerOf(params));
  EXPECT_EQ(p.world.room_x, 6.0);
  EXPECT_EQ(p.world.room_y, WorldConfig().room_y);
  EXPECT_EQ(p.world.wall_height, 0.5);
  EXPECT_EQ(p.world.brightness, 0.3);
  ASSERT_EQ(p.world.lights.size(), 2u);
  EXPECT_EQ(p.world.lights[0].x, 1.0);
  EXPECT_EQ(p.world.lights[0].intensity, LightConfig().intensity);
  EXPECT_EQ(p.world.lights[1].intensity, 0.2);
  ASSERT_EQ(p.world.boxes.size(), 1u);
  EXPECT_EQ(p.world.boxes[0].size_z, 0.4);
  EXPECT_EQ(p.world.boxes[0].yaw, 1.0);
  EXPECT_EQ(p.world.camera.width, 320);
  EXPECT_EQ(p.world.camera.height, CameraConfig().height);
  EXPECT_EQ(p.world.camera.horizontal_fov_deg, 60.0);
  EXPECT_EQ(p.noise.scale, 0.0);
  EXPECT_EQ(p.noise.dropout, 0.1);
  ASSERT_EQ(p.world.robots.size(), 2u);
  EXPECT_EQ(p.world.robots[0].start.x, -1.5);
  EXPECT_TRUE(p.world.robots[0].camera);
  EXPECT_EQ(p.world.robots[1].start.y, 2.0);
  EXPECT_TRUE(p.world.robots[1].left_marker);
  EXPECT_FALSE(p.world.robots[1].right_marker);
  EXPECT_TRUE(p.world.robots[1].back_marker);
  EXPECT_EQ(p.world.robots[1].slip.right, 0.05);
}

TEST(Params, EachRobotsMarkersTakeTheirColoursFromThePalette) {
  XmlRpcValue params = oneRobot();
  params["robots"][1] = std::string("duo");
  params["robots"][2] = std::string("trio");
  params["marker_colors"]["red"][0] = 0.85;
  params["marker_colors"]["red"][1] = 0;  // an int, as YAML writes 0
  params["marker_colors"]["red"][2] = 0.05;
  params["marker_colors"]["green"][0] = 0.0;  // the palette's own colours can be redrawn
  params["marker_colors"]["green"][1] = 1.0;
  params["marker_colors"]["green"][2] = 0.0;
  params["duo"]["y"] = 1.0;
  params["duo"]["markers"]["left"] = std::string("red");
  params["duo"]["markers"]["right"] = std::string("blue");
  params["trio"]["y"] = -1.0;
  params["trio"]["markers"]["left"] = std::string("red");
  params["trio"]["markers"]["back"] = std::string("green");
  params["trio"]["left_marker"] = false;  // the flag wins: sim.launch hides a cylinder so
  params["trio"]["right_marker"] = true;  // and a flag alone takes the default colour
  const WorldConfig world = simParamsFrom(readerOf(params)).world;
  ASSERT_EQ(world.marker_colors.count("red"), 1u);
  EXPECT_EQ(world.marker_colors.at("red").r, 0.85);
  EXPECT_EQ(world.marker_colors.at("red").g, 0.0);
  EXPECT_EQ(world.marker_colors.at("green").g, 1.0);
  EXPECT_EQ(world.marker_colors.at("orange").g, 0.45);  // the default palette stays
  const RobotConfig& solo = world.robots[0];
  EXPECT_FALSE(solo.left_marker || solo.right_marker || solo.back_marker);
  EXPECT_EQ(solo.left_color, "green");
  EXPECT_EQ(solo.right_color, "orange");
  EXPECT_EQ(solo.back_color, "blue");
  const RobotConfig& duo = world.robots[1];
  EXPECT_TRUE(duo.left_marker && duo.right_marker);
  EXPECT_FALSE(duo.back_marker);
  EXPECT_EQ(duo.left_color, "red");
  EXPECT_EQ(duo.right_color, "blue");
  const RobotConfig& trio = world.robots[2];
  EXPECT_FALSE(trio.left_marker);
  EXPECT_TRUE(trio.right_marker && trio.back_marker);
  EXPECT_EQ(trio.right_color, "orange");
  EXPECT_EQ(trio.back_color, "green");
}

TEST(Params, BadMarkersSayWhichAndWhy) {
  XmlRpcValue params = oneRobot();
  params["solo"]["markers"]["left"] = std::string("purple");
  EXPECT_EQ(errorOf(params), "robot 'solo': marker colour 'purple' is not in ~marker_colors");
  params["marker_colors"]["purple"] = std::string("#800080");
  EXPECT_EQ(errorOf(params), "~marker_colors/purple must be [r, g, b] (0..1)");
  params["marker_colors"]["purple"] = XmlRpcValue();
  params["marker_colors"]["purple"][0] = 0.5;
  params["marker_colors"]["purple"][1] = 0.0;
  params["marker_colors"]["purple"][2] = 2.0;
  EXPECT_EQ(errorOf(params), "marker colour 'purple' needs [r, g, b] within 0..1");
  params["marker_colors"]["purple"][2] = std::string("half");
  EXPECT_EQ(errorOf(params), "~marker_colors/purple must be a number");
  params["marker_colors"]["purple"][2] = 0.5;
  EXPECT_EQ(errorOf(params), "");
  params["solo"]["markers"]["top"] = std::string("purple");
  EXPECT_EQ(errorOf(params), "~solo/markers: top is not left, right or back");
  params["solo"]["markers"] = std::string("purple");
  EXPECT_EQ(errorOf(params), "~solo/markers must be {left: colour, right: colour, back: colour}");
  params["solo"]["markers"] = XmlRpcValue();
  params["solo"]["markers"]["left"] = 3;
  EXPECT_EQ(errorOf(params), "~solo/markers/left must name a colour");
  params = oneRobot();
  params["marker_colors"] = std::string("red");
  EXPECT_EQ(errorOf(params), "~marker_colors must be a dictionary");
}

TEST(Params, AWorldWithoutRobotsIsRefused) {
  XmlRpcValue params;
  EXPECT_EQ(errorOf(params), "~robots (list of names) is not set");
  params["robots"] = std::string("solo");  // not a list
  EXPECT_EQ(errorOf(params), "~robots (list of names) is not set");
  params["robots"] = XmlRpcValue();
  params["robots"][0] = 1;  // not names
  EXPECT_EQ(errorOf(params), "~robots (list of names) is not set");
}

TEST(Params, RobotsStartingInsideEachOtherAreRefused) {
  XmlRpcValue params = oneRobot();
  params["robots"][1] = std::string("duo");  // both at the default (0, 0)
  EXPECT_EQ(errorOf(params), "robots 'solo' and 'duo' start overlapping");
  params["duo"]["x"] = 0.3;  // less than two base radii (0.354 m) apart
  EXPECT_EQ(errorOf(params), "robots 'solo' and 'duo' start overlapping");
  params["duo"]["x"] = 0.4;
  EXPECT_EQ(errorOf(params), "");
}

TEST(Params, ABadWorldParameterSaysWhichAndWhy) {
  struct Case {
    const char* key;
    XmlRpcValue value;
    const char* error;
  };
  XmlRpcValue words(std::string("big"));
  XmlRpcValue room_words;
  room_words["size_x"] = std::string("big");
  XmlRpcValue light_words;
  light_words[0]["z"] = std::string("high");
  XmlRpcValue box_words;
  box_words[0]["size_x"] = true;
  XmlRpcValue camera_words;
  camera_words["hfov"] = std::string("wide");
  XmlRpcValue robot_words;
  robot_words["yaw"] = std::string("north");
  XmlRpcValue robot_camera;
  robot_camera["camera"] = 1;
  XmlRpcValue slipping;
  slipping["left_slip"] = 0.5;
  const Case cases[] = {
      {"room", words, "~room must be a dictionary"},
      {"room", room_words, "~room/size_x must be a number"},
      {"lights", words, "~lights must be a list of {x, y, z, intensity}"},
      {"lights", light_words, "~lights/z must be a number"},
      {"boxes", words, "~boxes must be a list of {x, y, z, size_x, size_y, size_z, yaw}"},
      {"boxes", box_words, "~boxes/size_x must be a number"},
      {"camera", words, "~camera must be a dictionary"},
      {"camera", camera_words, "~camera/hfov must be a number"},
      {"solo", words, "~solo must be a dictionary"},
      {"solo", robot_words, "~solo/yaw must be a number"},
      {"solo", robot_camera, "camera must be true or false"},
      {"solo", slipping, "robot 'solo': wheel slip must be in [0, 0.5)"},  // validate()
  };
  for (const Case& c : cases) {
    XmlRpcValue params = oneRobot();
    params[c.key] = c.value;
    EXPECT_EQ(errorOf(params), c.error) << c.key << " = " << c.value.toXml();
  }
}

TEST(Params, ABadNodeParameterSaysWhichAndWhy) {
  struct Case {
    const char* key;
    double value;
    const char* error;
  };
  const Case cases[] = {
      {"real_time_factor", -1.0, "rates must be > 0 and real_time_factor >= 0"},
      {"odom_rate", 0.0, "rates must be > 0 and real_time_factor >= 0"},
      {"camera_rate", -10.0, "rates must be > 0 and real_time_factor >= 0"},
      {"clock_rate", 0.0, "rates must be > 0 and real_time_factor >= 0"},
      {"frame_ack_timeout", 0.0, "~frame_ack_timeout must be in (0, 3600) s"},
      {"frame_ack_timeout", 3600.0, "~frame_ack_timeout must be in (0, 3600) s"},
      {"max_lockstep_factor", 0.19, "~max_lockstep_factor must be in [0.2, 1000]"},
      {"max_lockstep_factor", 1001.0, "~max_lockstep_factor must be in [0.2, 1000]"},
      {"control_rate", 0.0, "~control_rate must be in (0, 1000] Hz"},
      {"control_rate", 1000.5, "~control_rate must be in (0, 1000] Hz"},
      {"control_ack_timeout", 0.0, "~control_ack_timeout must be in (0, 3600) s"},
  };
  for (const Case& c : cases) {
    XmlRpcValue params = oneRobot();
    params[c.key] = c.value;
    EXPECT_EQ(errorOf(params), c.error) << c.key << " = " << c.value;
  }
  XmlRpcValue edges = oneRobot();  // the ends the ranges include
  edges["max_lockstep_factor"] = 0.2;
  edges["control_rate"] = 1000;
  EXPECT_EQ(errorOf(edges), "");
}

TEST(Params, TheDepthDropoutIsAProbabilityBelowOne) {
  XmlRpcValue params = oneRobot();
  params["camera"]["depth_dropout"] = 1.0;
  EXPECT_EQ(errorOf(params), "~camera/depth_dropout must be in [0, 1)");
  params["camera"]["depth_dropout"] = -0.1;
  EXPECT_EQ(errorOf(params), "~camera/depth_dropout must be in [0, 1)");
  params["camera"]["depth_dropout"] = std::string("some");
  EXPECT_EQ(errorOf(params), "~camera/depth_dropout must be a number");
  params["camera"]["depth_dropout"] = 0.0;
  params["camera"]["depth_noise"] = std::string("kinect");
  EXPECT_EQ(errorOf(params), "~camera/depth_noise must be a number");
}

TEST(Params, TheWorldIsCheckedBeforeTheNodesParameters) {
  XmlRpcValue params = oneRobot();
  params["odom_rate"] = 0.0;
  params["timestep"] = 0.5;
  EXPECT_EQ(errorOf(params), "timestep must be in (0, 0.01] s");
}

}  // namespace
}  // namespace rason_sim

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
