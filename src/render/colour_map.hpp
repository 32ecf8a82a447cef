// Colour maps for values on a surface, and the legend that says what the
// colours mean. Diverging (blue, grey, red: Moreland's cool-warm) for signed
// values such as mean curvature; sequential (viridis) for magnitudes such as
// a distance. Both stay readable under the pictures' shading and in grey.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace lbmshape::render {

struct Legend {
  std::string title;             // what the values are, with their unit
  double low = 0.0, high = 1.0;  // the ends of the map; values beyond are clamped
  bool diverging = false;        // low = -high, grey at 0
};

// t in [-1, 1]: blue, grey at 0, red.
glm::vec3 divergingColour(double t);
// t in [0, 1]: dark violet, teal, yellow.
glm::vec3 sequentialColour(double t);
// The colour of `value` on the legend's map.
glm::vec3 legendColour(const Legend& legend, double value);

}  // namespace lbmshape::render
