// The triangles of one cube of marching cubes: its case's loops of cut
// edges, each triangulated without the chords a neighbouring cube could
// also choose (loop_triangulation.hpp). Shared by the extraction from a
// whole grid and from the narrow band, so both make the same triangles.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "lbmshape/surface/cube_cases.hpp"
#include "lbmshape/surface/loop_triangulation.hpp"

namespace lbmshape {

// localPoint(edge) is the cube-local position of the vertex on a cube edge;
// emit(i, j, k) receives each triangle as three positions in c.edges.
template <class LocalPoint, class Emit>
void triangulateCubeCase(const cube::CubeCase& c, LocalPoint&& localPoint, Emit&& emit)
{
  std::array<glm::dvec3, 12> points;
  std::array<glm::u8vec3, maxLoopSize - 2> local;
  int first = 0;
  for (int loop = 0; loop < c.loopCount; ++loop) {
    const int size = c.loopSize[loop];
    int count = 0;
    if (size == 3) {
      local[0] = glm::u8vec3(0, 1, 2);
      count = 1;
    } else {
      for (int i = 0; i < size; ++i) points[i] = localPoint(c.edges[first + i]);
      count = triangulateLoop(points.data(), size, c.blockedChords.data() + first, local);
    }
    // Every loop of the table has a triangulation without blocked chords
    // (the tests check all 256 cases), so the fan is never used; it only
    // keeps the triangle count right.
    if (count != size - 2) {
      count = size - 2;
      for (int i = 0; i < count; ++i) local[i] = glm::u8vec3(0, i + 1, i + 2);
    }
    for (int i = 0; i < count; ++i) emit(first + local[i][0], first + local[i][1], first + local[i][2]);
    first += size;
  }
}

}  // namespace lbmshape
