// What the device's distance shader (band_distance.comp) and its host side
// (src/sdf/device_band_distances.cpp) agree on, written once for both: GLSL
// includes this file, and so does C++.
//
// The tree and its triangles are in grid coordinates (cell (x, y, z)'s
// centre at (x, y, z)), as floats:
//   nodes: TriangleBvh's nodes in their order, depth first: a leaf's
//     triangles are slots [first, first + count); an inner node (count 0)
//     has its first child next to it and its second at `first`
//   triangles: per slot, four vec4: the corners a, b, c, and the unit
//     normal; a.w is 1 for a sliver (measured as PreparedTriangle does, on
//     the mesh's doubles), which counts as its three edges
//   origins: ivec4 per brick slot, the brick's first cell
//   distances: float per stored cell (BandCells numbering) of the chunk
#ifndef LBMSHAPE_BAND_DISTANCE_INTERFACE_H
#define LBMSHAPE_BAND_DISTANCE_INTERFACE_H

#define BAND_DISTANCE_WORKGROUP_SIZE 64
// TriangleBvh::kMaxDepth + 2: a walk of any tree it builds fits the
// traversal's fixed stack (device_band_distances.cpp asserts it).
#define BAND_DISTANCE_STACK 130

#define BAND_DISTANCE_BINDING_NODES 0
#define BAND_DISTANCE_BINDING_TRIANGLES 1
#define BAND_DISTANCE_BINDING_ORIGINS 2
#define BAND_DISTANCE_BINDING_DISTANCES 3

// The push constants: the chunk's bricks [firstSlot, firstSlot + slots),
// the grid's extent (cells beyond it get +inf), and the squared distance
// (voxels^2) beyond which nothing is searched (+inf for none).
#define BAND_DISTANCE_PARAMETERS(FIELD) \
  FIELD(int, firstSlot)                 \
  FIELD(int, slots)                     \
  FIELD(int, nx)                        \
  FIELD(int, ny)                        \
  FIELD(int, nz)                        \
  FIELD(float, bound2)

#define BAND_DISTANCE_DECLARE_FIELD(type, name) type name;

#ifdef __cplusplus
#include <cstdint>
namespace lbmshape::band_distance_shader {
struct Parameters {
  BAND_DISTANCE_PARAMETERS(BAND_DISTANCE_DECLARE_FIELD)
};
static_assert(sizeof(Parameters) == 6 * 4, "push constants: 6 words");
// One node as the shader reads it (std430: a vec3 and a uint share 16 bytes).
struct Node {
  float lo[3];
  uint32_t first;
  float hi[3];
  uint32_t count;
};
static_assert(sizeof(Node) == 32, "nodes: 32 bytes");
}  // namespace lbmshape::band_distance_shader
#endif

#endif
