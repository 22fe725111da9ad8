// Marker colours: the palette, the MJCF's materials and what the camera renders of them.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "rason_sim/markers.h"
#include "rason_sim/mjcf_model.h"
#include "rason_sim/renderer.h"
#include "rason_sim/world.h"

using namespace rason_sim;

namespace {

const Rgb kRed{0.85, 0.05, 0.05};
const Rgb kYellow{0.85, 0.8, 0.05};

WorldConfig twoRobots() {
  WorldConfig world;
  world.lights.push_back(LightConfig());
  RobotConfig eye;
  eye.name = "eye";
  eye.start = {-0.75, 0.0, 0.0};
  eye.camera = true;
  RobotConfig seen;
  seen.name = "seen";
  seen.start = {0.75, 0.0, 0.0};  // 1.5 m ahead of the camera, facing away from it
  seen.left_marker = seen.right_marker = true;
  world.robots = {eye, seen};
  return world;
}

double hueGap(double a, double b) {
  const double d = std::fabs(a - b);
  return std::min(d, 360.0 - d);
}

}  // namespace

TEST(Markers, HueOfPrimariesSecondariesAndGrey) {
  EXPECT_NEAR(hueDeg({1, 0, 0}), 0.0, 1e-9);
  EXPECT_NEAR(hueDeg({1, 1, 0}), 60.0, 1e-9);
  EXPECT_NEAR(hueDeg({0, 1, 0}), 120.0, 1e-9);
  EXPECT_NEAR(hueDeg({0, 0, 1}), 240.0, 1e-9);
  EXPECT_NEAR(hueDeg({1, 0, 1}), 300.0, 1e-9);
  EXPECT_NEAR(hueDeg({1, 0, 0.1}), 354.0, 1e-9);
  EXPECT_LT(hueDeg({0.4, 0.4, 0.4}), 0.0);
}

TEST(Markers, ThePaletteRefusesBadNamesAndComponents) {
  MarkerPalette palette = defaultMarkerPalette();
  EXPECT_NO_THROW(validatePalette(palette));
  palette["Red"] = kRed;
  EXPECT_THROW(validatePalette(palette), std::invalid_argument);
  palette.erase("Red");
  palette["red"] = {1.2, 0, 0};
  EXPECT_THROW(validatePalette(palette), std::invalid_argument);
  palette["red"] = {std::nan(""), 0, 0};
  EXPECT_THROW(validatePalette(palette), std::invalid_argument);
}

TEST(Markers, TheCaseStudysColoursAreRenderedAsBefore) {
  WorldConfig world = twoRobots();
  world.robots[1].back_marker = true;
  const std::string xml = buildMjcf(world);
  EXPECT_NE(xml.find("<material name='marker_green' rgba='0.05 0.65 0.15 1' specular='0.1'/>"), std::string::npos);
  EXPECT_NE(xml.find("<material name='marker_orange' rgba='1 0.45 0 1' specular='0.1'/>"), std::string::npos);
  EXPECT_NE(xml.find("<material name='marker_blue' rgba='0.1 0.3 0.95 1' specular='0.1'/>"), std::string::npos);
  EXPECT_NE(xml.find("name='seen_left_marker' type='cylinder' size='0.02 0.165' pos='0 0.1135 0.285' "
                     "mass='0.02' material='marker_green'"), std::string::npos);
  EXPECT_NE(xml.find("name='seen_right_marker' type='cylinder' size='0.02 0.165' pos='0 -0.1135 0.285' "
                     "mass='0.02' material='marker_orange'"), std::string::npos);
  EXPECT_NE(xml.find("name='seen_back_marker' type='cylinder' size='0.02 0.165' pos='-0.12 0 0.285' "
                     "mass='0.02' material='marker_blue'"), std::string::npos);
}

TEST(Markers, AColourNotInThePaletteIsRefused) {
  WorldConfig world = twoRobots();
  world.robots[1].left_color = "red";
  try {
    validate(world);
    FAIL() << "a colour outside the palette was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "robot 'seen': marker colour 'red' is not in ~marker_colors");
  }
  world.marker_colors["red"] = kRed;
  EXPECT_NO_THROW(validate(world));
}

// The camera sees each cylinder in its robot's own colour, on the robot's side: facing
// away, its left cylinder is on the image's left.
TEST(Markers, TheCameraSeesEachCylinderInItsOwnColour) {
  WorldConfig world = twoRobots();
  world.marker_colors["red"] = kRed;
  world.marker_colors["yellow"] = kYellow;
  world.robots[1].left_color = "red";
  world.robots[1].right_color = "yellow";
  mjModel* model = compileMjcf(buildMjcf(world));
  mjData* data = mj_makeData(model);
  mj_forward(model, data);
  const int width = world.camera.width, height = world.camera.height;
  std::vector<unsigned char> rgb;
  std::vector<float> depth;
  {
    OffscreenRenderer renderer(model, width, height);
    SceneSnapshot snapshot(model);
    snapshot.take(model, data, mj_name2id(model, mjOBJ_CAMERA, cameraName("eye").c_str()));
    renderer.render(snapshot.scene(), rgb, depth);
  }
  mj_deleteData(data);
  mj_deleteModel(model);

  int red = 0, yellow = 0, other = 0;
  double red_column = 0.0, yellow_column = 0.0;
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const unsigned char* p = &rgb[3 * (static_cast<size_t>(row) * width + column)];
      const Rgb pixel{p[0] / 255.0, p[1] / 255.0, p[2] / 255.0};
      const double high = std::max({pixel.r, pixel.g, pixel.b});
      const double low = std::min({pixel.r, pixel.g, pixel.b});
      if (high < 0.05 || (high - low) / high < 0.5) continue;  // dark or greyish: no marker
      const double hue = hueDeg(pixel);
      if (hueGap(hue, hueDeg(kRed)) < 10.0) {
        ++red;
        red_column += column;
      } else if (hueGap(hue, hueDeg(kYellow)) < 10.0) {
        ++yellow;
        yellow_column += column;
      } else {
        ++other;
      }
    }
  ASSERT_GT(red, 300);
  ASSERT_GT(yellow, 300);
  EXPECT_EQ(other, 0);
  EXPECT_LT(red_column / red, width / 2.0);
  EXPECT_GT(yellow_column / yellow, width / 2.0);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
