// Where marching cubes puts the vertex of a cut grid edge, and its normal:
// shared by the extraction from a whole grid and from the narrow band, so
// that both give the same vertex for the same samples.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "lbmshape/core/extent.hpp"

namespace lbmshape::edge_vertex {

// Vertices stay this fraction of an edge away from its ends: with a sample
// equal to the isovalue, several edges would otherwise put their vertices on
// the same grid point and the triangles between them would have no area.
inline constexpr double margin = 1e-3;

// Where along the edge from sample a to sample b the field crosses iso.
inline double crossing(float a, float b, float iso)
{
  const double t = (double(a) - iso) / (double(a) - double(b));
  return std::clamp(t, margin, 1.0 - margin);
}

// The field's gradient at a sample by central differences (one-sided at the
// grid's faces); `at(x, y, z)` reads a sample.
template <class Sampler>
glm::dvec3 gradient(const Sampler& at, const Extent3& e, int x, int y, int z)
{
  glm::dvec3 g;
  const int n[3] = {e.nx, e.ny, e.nz};
  for (int axis = 0; axis < 3; ++axis) {
    int c[3] = {x, y, z};
    const int lo = std::max(c[axis] - 1, 0), hi = std::min(c[axis] + 1, n[axis] - 1);
    if (hi == lo) {
      g[axis] = 0.0;
      continue;
    }
    int a[3] = {x, y, z}, b[3] = {x, y, z};
    a[axis] = lo;
    b[axis] = hi;
    g[axis] = (double(at(b[0], b[1], b[2])) - double(at(a[0], a[1], a[2]))) / (hi - lo);
  }
  return g;
}

// The unit normal at the vertex t along an edge (`axis`) between samples
// with gradients ga and gb: -grad X interpolated (pointing out, from X > iso
// to X < iso); along the edge, out of the inside sample, where the field is
// flat.
inline glm::vec3 normal(const glm::dvec3& ga, const glm::dvec3& gb, double t, int axis, bool lowerInside)
{
  glm::dvec3 outward = -((1.0 - t) * ga + t * gb);
  const double length = glm::length(outward);
  if (length > 0.0 && std::isfinite(length)) return glm::vec3(outward / length);
  outward = glm::dvec3(0.0);
  outward[axis] = lowerInside ? 1.0 : -1.0;
  return glm::vec3(outward);
}

}  // namespace lbmshape::edge_vertex
