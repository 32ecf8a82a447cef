// Triangulation of one marching-cubes loop (a closed polygon of up to 12
// edge vertices, usually not planar). Of all triangulations that avoid the
// blocked chords, it takes the one whose worst triangle is best, where a
// triangle scores its shape (1 for equilateral, 0 for a sliver) times the
// cosine between its normal and the loop's vector area: slivers and folded
// triangles lose. The choice depends only on the points, so it is the same
// whichever thread makes it.
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace lbmshape {

constexpr int maxLoopSize = 12;

// Writes size - 2 triangles of loop positions, each wound like the loop,
// into `triangles` and returns their count; returns 0 when every
// triangulation needs a blocked chord (bit j of blocked[i]: no chord i-j).
int triangulateLoop(const glm::dvec3* points, int size, const uint16_t* blocked,
                    std::array<glm::u8vec3, maxLoopSize - 2>& triangles);

}  // namespace lbmshape
