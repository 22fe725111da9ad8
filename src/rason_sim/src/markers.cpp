#include "rason_sim/markers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rason_sim {

MarkerPalette defaultMarkerPalette() {
  return {{"green", {0.05, 0.65, 0.15}}, {"orange", {1.0, 0.45, 0.0}}, {"blue", {0.1, 0.3, 0.95}}};
}

std::string markerMaterial(const std::string& colour) { return "marker_" + colour; }

double hueDeg(const Rgb& c) {
  const double high = std::max({c.r, c.g, c.b});
  const double span = high - std::min({c.r, c.g, c.b});
  if (span <= 0.0) return -1.0;
  double hue;
  if (high == c.r)
    hue = 60.0 * std::fmod((c.g - c.b) / span + 6.0, 6.0);
  else if (high == c.g)
    hue = 60.0 * ((c.b - c.r) / span + 2.0);
  else
    hue = 60.0 * ((c.r - c.g) / span + 4.0);
  return hue >= 360.0 ? hue - 360.0 : hue;
}

void validatePalette(const MarkerPalette& palette) {
  for (const auto& entry : palette) {
    const std::string& name = entry.first;
    if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
      throw std::invalid_argument("marker colour '" + name + "' must be a name of a-z, 0-9 and _");
    const Rgb& c = entry.second;
    for (double component : {c.r, c.g, c.b})
      if (!(component >= 0.0 && component <= 1.0))
        throw std::invalid_argument("marker colour '" + name + "' needs [r, g, b] within 0..1");
  }
}

}  // namespace rason_sim
