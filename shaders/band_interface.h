// What the narrow-band shaders (band_step.comp, band_feature_rule.comp) and their host side
// (src/lbm/band_vulkan_solver.cpp) agree on, written once for both: GLSL
// includes this file, and so does C++.
//
// Layouts, per brick slot s (a brick is 8 x 8 x 8 cells, cell
// l = x + 8 y + 64 z), all as vec4 of four consecutive cells of a row:
//   moments: [s][m][l / 4]: m = 0..3 for rho*, jx*, jy*, jz* after the last collision
//   field, omega, gamma, source base: [s][l / 4] (the order of BandField's values)
// and as words:
//   streams: uint [s][y + 8 z], bit x set when cell (x, y, z) streams
//   neighbours: ivec4 [s][(dy + 1) + 3 (dz + 1)]: the slots of the bricks
//     at (-1, dy, dz), (0, dy, dz) and (1, dy, dz) from brick s, -1 for
//     none, and a 0: a row's brick and the two beside it in one fetch
//   origins: ivec4 [s]: the brick's first cell in the grid
//   work: int [w]: the slot each workgroup updates, from workOffset on (a
//     step skips the bricks that never change; the field pass reads all)
//
// Reads go through texel buffers (one view can span far more than a
// storage-buffer binding, 128 MiB on lavapipe, and a vec4 texel fetch is
// the cheapest load there); writes go to storage buffers split into pools
// of whole bricks, each pool one binding within the device's range limit.
#ifndef LBMSHAPE_BAND_INTERFACE_H
#define LBMSHAPE_BAND_INTERFACE_H

#define BAND_WORKGROUP_SIZE 64  // one brick: its 64 rows of eight cells
#define BAND_MAX_WORKGROUPS_X 65535
#define BAND_MAX_POOLS 16
// The field's and the omega buffer's pools: a float a cell, so a pool holds
// four times a moment pool's bricks, and four reach as far as the moments'
// sixteen. (Every storage-buffer binding counts against the device's
// per-stage limit: 32 on lavapipe.)
#define BAND_MAX_FIELD_POOLS (BAND_MAX_POOLS / 4)

// Bindings of set 0.
#define BAND_BINDING_MOMENTS 0     // samplerBuffer, the current copy
#define BAND_BINDING_STREAMS 1     // usamplerBuffer
#define BAND_BINDING_NEIGHBOURS 2  // isamplerBuffer (RGBA32I)
#define BAND_BINDING_ORIGINS 3     // isamplerBuffer (RGBA32I)
#define BAND_BINDING_OMEGA 4       // samplerBuffer
#define BAND_BINDING_SOURCE 5      // samplerBuffer
#define BAND_BINDING_NEXT 6        // storage buffers [BAND_MAX_POOLS]: the next copy
#define BAND_BINDING_FIELD 7       // storage buffers [BAND_MAX_POOLS]: the field
#define BAND_BINDING_WORK 8        // isamplerBuffer
// Storage buffers [BAND_MAX_POOLS], pooled as the field: the omega buffer
// written (gamma per cell under the paper's rule, the feature rule's
// omega), which BAND_BINDING_OMEGA reads. Not a storage texel buffer: on
// lavapipe the feature rule's two image stores an invocation took its pass
// from 7 to 17 ms at --res 128.
#define BAND_BINDING_OMEGA_OUT 9

// What a dispatch of band_step.comp does (the push constant `pass`): one
// pipeline a run for all of it, since lavapipe spends some 100 ms on each.
#define BAND_PASS_FIELD 0           // X of every stored cell to the field buffer
#define BAND_PASS_STEP 1            // a lattice step
// X into the copy of the moments that the next step would write, where its
// rho* goes: the older copy is spent (the solver counts it so). The
// feature rule (band_feature_rule.comp) reads it there.
#define BAND_PASS_FIELD_TO_OLDER 2

// Specialization constants.
#define BAND_SPEC_W_REST 0
#define BAND_SPEC_W_AXIAL 1
#define BAND_SPEC_W_DIAGONAL 2
#define BAND_SPEC_HAS_SOURCE 3  // the morph's source term
#define BAND_SPEC_PAPER_RULE 4  // the paper's anisotropic rule

// The push constants, as a list of (type, name) for both languages.
#define BAND_STEP_PARAMETERS(FIELD) \
  FIELD(int, nx)                    \
  FIELD(int, ny)                    \
  FIELD(int, nz)                    \
  FIELD(int, workOffset)            \
  FIELD(int, works)                 \
  FIELD(int, slotsPerMomentPool)    \
  FIELD(int, slotsPerFieldPool)     \
  FIELD(float, omega)               \
  FIELD(float, decay)               \
  FIELD(float, baseScale)           \
  FIELD(float, gamma0)              \
  FIELD(int, pass) /* BAND_PASS_*: what the dispatch does */               \
  FIELD(int, perCellOmega) /* 1: omega from the omega buffer */                  \
  FIELD(float, kappaEdge)  /* the feature rule's (band_feature_rule.comp) */      \
  FIELD(float, lowestGamma) /* its lowest gamma, min(ADAPTIVE_GAMMA_LOWEST, gamma0) */ \
  FIELD(int, writeField)   /* 1: a step also stores the X it pulled, as the field pass... */ \
  FIELD(float, fieldDecay) /* ... under a source of this decay and scale */ \
  FIELD(float, fieldBaseScale)

// vec4 index of moment m (0..3) of row `row` (y + 8 z), half `half` (cells
// 0-3 or 4-7) of brick slot s, in a copy of the moments.
#define BAND_MOMENT_INDEX(s, m, row, half) ((((s) * 4 + (m)) * 64 + (row)) * 2 + (half))

// The surface-speed pass (band_speed.comp): for every row of every brick
// slot s, over its cells with |X older| < 1, the sum of |X newer - X older| and their number,
// from rho* of the two copies (the fields of the last two steps when there
// is no source: BandSolver::storedField).
#define BAND_SPEED_BINDING_NEWER 0     // samplerBuffer: the newer copy of the moments
#define BAND_SPEED_BINDING_OLDER 1     // samplerBuffer: the older copy
#define BAND_SPEED_BINDING_PARTIALS 2  // storage buffer, vec2 [s][row]: (sum, count)
#define BAND_SPEED_PARAMETERS(FIELD) FIELD(int, slots)

#define BAND_DECLARE_FIELD(type, name) type name;

#ifdef __cplusplus
namespace lbmshape::band_shader {
struct StepParameters {
  BAND_STEP_PARAMETERS(BAND_DECLARE_FIELD)
};
static_assert(sizeof(StepParameters) == 18 * 4, "push constants: 18 words");
struct SpeedParameters {
  BAND_SPEED_PARAMETERS(BAND_DECLARE_FIELD)
};
}  // namespace lbmshape::band_shader
#endif

#endif
