// The colours of the robots' marker cylinders: a palette of named colours (the world
// file's ~marker_colors, over the case study's green, orange and blue) that each robot's
// left, right and back cylinders take their colour from. No ROS, no MuJoCo.
#pragma once

#include <map>
#include <string>

namespace rason_sim {

struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;  // 0..1, the material's diffuse colour
};

using MarkerPalette = std::map<std::string, Rgb>;

// green, orange and blue as the thesis's case study has always rendered them.
MarkerPalette defaultMarkerPalette();

// The MJCF material of a palette colour.
std::string markerMaterial(const std::string& colour);

// HSV hue in degrees [0, 360) (red 0, yellow 60, green 120, ...); negative for a grey,
// which has none.
double hueDeg(const Rgb& colour);

// Throws std::invalid_argument: a name that is not [a-z0-9_]+, a component outside [0, 1].
void validatePalette(const MarkerPalette& palette);

}  // namespace rason_sim
