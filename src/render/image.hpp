// A picture in memory: 8-bit RGBA, rows top to bottom, as PNG stores them.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace lbmshape::render {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(size_t(w) * size_t(h) * 4, 255) {}

  uint8_t* pixel(int x, int y) { return rgba.data() + (size_t(y) * size_t(width) + size_t(x)) * 4; }
  const uint8_t* pixel(int x, int y) const { return rgba.data() + (size_t(y) * size_t(width) + size_t(x)) * 4; }
  glm::vec3 colour(int x, int y) const
  {
    const uint8_t* p = pixel(x, y);
    return glm::vec3(p[0], p[1], p[2]) / 255.0f;
  }
  // Opaque fill of the rectangle [x0, x1) x [y0, y1), clipped to the picture.
  void fill(int x0, int y0, int x1, int y1, glm::vec3 colour);
};

}  // namespace lbmshape::render
