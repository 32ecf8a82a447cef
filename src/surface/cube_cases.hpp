// The marching-cubes case table, generated at start-up from one rule per cube
// face instead of typed in. On a face the surface is a set of segments
// between the face's cut edges; on a face with two diagonal inside corners
// (the ambiguous face) the rule always separates the inside corners. The rule
// reads only the face's four samples, so the two cubes that share a face draw
// the same segments on it, in opposite directions, and the extracted surface
// has no cracks and a consistent orientation by construction. The segments of
// a cube chain into closed loops, which marching_cubes.cpp triangulates.
#pragma once

#include <array>
#include <cstdint>

namespace lbmshape::cube {

// Corner c sits at offset (c & 1, (c >> 1) & 1, (c >> 2) & 1) of the cube;
// bit c of a case index is set when corner c is inside.
constexpr int cornerOffset(int corner, int axis) { return (corner >> axis) & 1; }

// Edge e runs along axis e / 4 from corner `lower` to corner `upper`; e % 4
// holds the offsets along the other two axes, the lower-numbered axis in bit 0.
struct Edge {
  uint8_t axis;
  uint8_t lower, upper;
};
const std::array<Edge, 12>& edges();

// Face axis * 2 + side, with side 0 at the low coordinate.
struct Face {
  uint8_t axis, side;
  std::array<uint8_t, 4> corners;  // counter-clockwise seen from outside the cube
};
const std::array<Face, 6>& faces();

// The surface inside one cube: closed loops of cut edges, each wound
// counter-clockwise seen from outside the inside region (so its triangles
// face outward). Loops are stored one after another in `edges`.
struct CubeCase {
  static constexpr int maxLoops = 4;
  uint8_t loopCount = 0;
  uint8_t edgeCount = 0;                     // cut edges = loop vertices in all
  std::array<uint8_t, maxLoops> loopSize{};  // vertices in each loop
  std::array<uint8_t, 12> edges{};
  // blockedChords[i] has bit j set when loop vertices i and j (same loop) lie
  // on one cube face without a segment between them. The cube on the other
  // side of that face could choose the same chord, which would give that mesh
  // edge four triangles; so no triangulation may use it.
  std::array<uint16_t, 12> blockedChords{};

  int triangleCount() const { return edgeCount - 2 * loopCount; }
};

const std::array<CubeCase, 256>& cubeCases();

}  // namespace lbmshape::cube
