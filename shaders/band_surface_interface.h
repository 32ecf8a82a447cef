// What the device's marching cubes on the narrow band (band_surface.comp)
// and its host side (src/lbm/band_surface_pass.cpp, src/surface/surface_pieces.hpp)
// agree on, written once for both: GLSL includes this file, and so does C++.
//
// The pass reads the field buffer (a float a stored cell, BandField's order)
// and lists the pieces of the surface X = iso that a frame needs, in place
// of the field itself:
//   crossings: every cut grid edge of a cube whose lower corner lies in a
//     stored brick (and whose upper corner in the grid), as two uvec4:
//     (key low, key high, floatBits(X at the lower end), floatBits(X at the
//     upper end)), (floatBits(normal x), y, z, 0); key = 3 * grid index of
//     the lower end + axis. An edge that the cubes of several bricks share
//     (up to four) may be listed by each (the host keeps one).
//   cubes: every such cube that the surface cuts, as a uvec4: (index low,
//     index high, case, slot * 512 + cell in brick), index the grid index
//     of its lower corner; the last orders the cubes as the CPU's marching
//     cubes does (brick by brick), so that both make their triangles in the
//     same order.
//   counters: uint [4]: crossings and cubes found (the pass writes only
//     those within the buffers' capacities, and the host runs it again with
//     larger ones when either was exceeded), floatBits of the largest
//     |X - base| over the cells with |base| <= nearBand (the morph's
//     distance to its target, base being X_target), and the number of
//     stored values that are not finite.
//   probe values: X at the listed stored cells (a morph's frame report
//     samples the frame's field near the target's surface), in their order.
#ifndef LBMSHAPE_BAND_SURFACE_INTERFACE_H
#define LBMSHAPE_BAND_SURFACE_INTERFACE_H

#define SURFACE_BINDING_FIELD 0       // samplerBuffer (R32F): the field buffer
#define SURFACE_BINDING_NEIGHBOURS 1  // isamplerBuffer: band_interface.h's neighbours
#define SURFACE_BINDING_ORIGINS 2     // isamplerBuffer: band_interface.h's origins
#define SURFACE_BINDING_FAR_SIDES 3   // usamplerBuffer (R32UI), per slot: bit (dx+1) + 3 (dy+1) + 9 (dz+1) set
                                      // when the brick there is not stored and its far side is inside
#define SURFACE_BINDING_BASE 4        // samplerBuffer (RGBA32F): the source's base, per cell as the field
#define SURFACE_BINDING_COUNTERS 5    // storage buffer, uint [4]
#define SURFACE_BINDING_CROSSINGS 6   // storage buffer, uvec4 [2 per crossing]
#define SURFACE_BINDING_CUBES 7       // storage buffer, uvec4 [cube]
#define SURFACE_BINDING_PROBES 8      // isamplerBuffer (R32I): stored cells (slot * 512 + cell in brick)
#define SURFACE_BINDING_PROBE_VALUES 9  // storage buffer, float [probe]

#define SURFACE_COUNTER_CROSSINGS 0
#define SURFACE_COUNTER_CUBES 1
#define SURFACE_COUNTER_ERROR 2
#define SURFACE_COUNTER_NOT_FINITE 3
#define SURFACE_COUNTERS 4

#define SURFACE_PARAMETERS(FIELD)                                             \
  FIELD(int, nx)                                                              \
  FIELD(int, ny)                                                              \
  FIELD(int, nz)                                                              \
  FIELD(int, slots)                                                           \
  FIELD(float, iso)                                                           \
  FIELD(float, farValue)                                                      \
  FIELD(float, nearBand) /* negative: no base, no error */                    \
  FIELD(int, crossingCapacity)                                                \
  FIELD(int, cubeCapacity)                                                    \
  FIELD(int, probes)

#define SURFACE_DECLARE_FIELD(type, name) type name;

#ifdef __cplusplus
#include <cstdint>
namespace lbmshape::surface_shader {
struct Parameters {
  SURFACE_PARAMETERS(SURFACE_DECLARE_FIELD)
};
static_assert(sizeof(Parameters) == 10 * 4, "push constants: 10 words");
}  // namespace lbmshape::surface_shader
#endif

#endif
