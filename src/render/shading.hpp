// The pictures' light on the CPU: the formula of render_surface.frag, from
// the constants both include (render_interface.h). The tests compare the
// pixels the device draws with it.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "lbmshape/shaders/render_interface.h"

namespace lbmshape::render {

inline glm::dvec3 lightDirection() { return {RENDER_LIGHT_X, RENDER_LIGHT_Y, RENDER_LIGHT_Z}; }
inline glm::dvec3 backgroundColour() { return {RENDER_BACKGROUND_RGB}; }
inline glm::dvec3 lineColour() { return {RENDER_LINE_RGB}; }

// The colour of a surface of colour `base` whose normal, in view space, is
// `viewNormal` (x right, y up, z towards the viewer).
inline glm::dvec3 shade(glm::dvec3 base, glm::dvec3 viewNormal)
{
  glm::dvec3 n = glm::normalize(viewNormal);
  if (n.z < 0.0) n = -n;
  const glm::dvec3 light = lightDirection();
  const glm::dvec3 halfway = glm::normalize(light + glm::dvec3(0.0, 0.0, 1.0));
  const double diffuse = std::max(glm::dot(n, light), 0.0);
  const double specular = std::pow(std::max(glm::dot(n, halfway), 0.0), RENDER_SHININESS);
  const glm::dvec3 lit = base * (RENDER_AMBIENT + RENDER_DIFFUSE * diffuse) + RENDER_SPECULAR * specular;
  return glm::min(lit, glm::dvec3(1.0));
}

}  // namespace lbmshape::render
