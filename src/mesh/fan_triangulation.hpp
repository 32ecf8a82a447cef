// Polygons of a face list become triangle fans.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/core/log.hpp"

namespace lbmshape {

// Appends the fan (c0, ck, ck+1) of a polygon's corners, leaving out the
// triangles that repeat a corner: they have no area, validation would drop
// them anyway, and a line like "f 1 1 1 1 ..." must not turn two bytes of a
// file into twelve of triangles. Exact for the convex polygons files
// normally hold.
inline void appendFan(const std::vector<uint32_t>& corners, std::vector<glm::uvec3>& triangles)
{
  for (size_t k = 1; k + 1 < corners.size(); ++k) {
    const uint32_t a = corners[0], b = corners[k], c = corners[k + 1];
    if (a != b && b != c && a != c) triangles.emplace_back(a, b, c);
  }
}

// The one warning of the face-list readers (OBJ, OFF, PLY) for the faces of
// fewer than three corners they passed over.
inline void warnOfShortFaces(const std::string& name, size_t shortFaces)
{
  if (shortFaces == 0) return;
  log::warning(name + ": skipped " + std::to_string(shortFaces) + (shortFaces == 1 ? " face" : " faces") +
               " with fewer than 3 corners");
}

}  // namespace lbmshape
