// sRGB, in which lbmshape keeps vertex colours (as screens and PNG show
// them), and the linear RGB of glTF's COLOR_0 (glTF 2.0, 3.7.2.1).
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace lbmshape {

inline float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
inline float linearToSrgb(float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

}  // namespace lbmshape
