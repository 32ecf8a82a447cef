#include "lbmshape/render/image.hpp"

#include <algorithm>

namespace lbmshape::render {

void Image::fill(int x0, int y0, int x1, int y1, glm::vec3 colour)
{
  x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, width), y1 = std::min(y1, height);
  const glm::vec3 c = glm::clamp(colour, 0.0f, 1.0f) * 255.0f + 0.5f;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      uint8_t* p = pixel(x, y);
      p[0] = uint8_t(c.r), p[1] = uint8_t(c.g), p[2] = uint8_t(c.b), p[3] = 255;
    }
}

}  // namespace lbmshape::render
