// A field of the grid (Volume or BandField: anything with extent() and
// at(x, y, z)) read between its cells.
#pragma once

#include <utility>

#include <glm/glm.hpp>

#include "lbmshape/core/extent.hpp"

namespace lbmshape {

// X and its gradient at a point of the grid (cell units), trilinear between
// the eight cells around it; outside the grid, at the nearest point inside.
template <class Field>
std::pair<double, glm::dvec3> sampleWithGradient(const Field& field, glm::dvec3 g)
{
  const Extent3& e = field.extent();
  g = glm::clamp(g, glm::dvec3(0.0), glm::dvec3(e.nx - 1, e.ny - 1, e.nz - 1));
  const glm::ivec3 lo = glm::min(glm::ivec3(glm::floor(g)), glm::ivec3(e.nx - 2, e.ny - 2, e.nz - 2));
  const glm::dvec3 t = g - glm::dvec3(lo);
  double c[2][2][2];
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) c[dz][dy][dx] = field.at(lo.x + dx, lo.y + dy, lo.z + dz);
  double value = 0.0;
  glm::dvec3 gradient(0.0);
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const double wx = dx ? t.x : 1.0 - t.x, wy = dy ? t.y : 1.0 - t.y, wz = dz ? t.z : 1.0 - t.z;
        const double v = c[dz][dy][dx];
        value += wx * wy * wz * v;
        gradient +=
            v * glm::dvec3((dx ? 1.0 : -1.0) * wy * wz, (dy ? 1.0 : -1.0) * wx * wz, (dz ? 1.0 : -1.0) * wx * wy);
      }
  return {value, gradient};
}

}  // namespace lbmshape
