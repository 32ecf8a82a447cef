// Shared by lbm_step.comp and lbm_field.comp: the bindings they read and the
// pull-streaming of the 19 distributions of four consecutive cells.
//
// Each invocation updates cells x0..x0+3 of one row. Lavapipe executes every
// buffer load and store one SIMD lane at a time and runs divergent branches
// with both sides masked, so the pull is written with as few memory
// instructions as possible and without branches.

#include "lattice_layout.glsl"
#include "lattice_interface.h"

layout(local_size_x_id = 0) in;
layout(constant_id = LATTICE_SPEC_PER_CELL_OMEGA) const bool PER_CELL_OMEGA = false;
layout(constant_id = LATTICE_SPEC_HAS_SOURCE) const bool HAS_SOURCE = false;

layout(push_constant) uniform StepParameters { LATTICE_STEP_PARAMETERS(LATTICE_DECLARE_FIELD) } params;

// Post-collision distributions of the previous step: the whole lattice copy,
// read as vec4 (four cells of one direction).
layout(set = 0, binding = LATTICE_BINDING_IN) uniform samplerBuffer lattice;
layout(set = 0, binding = LATTICE_BINDING_OMEGA) uniform samplerBuffer omegaPerCell;  // 1/tau per cell
layout(set = 0, binding = LATTICE_BINDING_SOURCE) uniform samplerBuffer sourceBase;   // A per cell

int ownBlock, cellY, cellZ;  // this invocation's block and row
bool firstInRow;             // cell x0 is at the x = 0 wall
bvec4 pastRowEnd;            // per lane: the upstream neighbour along -x is beyond x = NX - 1
int lastLane;                // the lane of cell NX - 1 if it is in this block, else 3
vec4 f[19];                  // the four cells' distributions after streaming

// f[I] = f*_I(r - e_I), or f*_O(r) where r - e_I is outside (bounce-back),
// for direction I with velocity (EX, EY, EZ) and opposite O = -e_I. One vec4
// fetch, plus, for the x-moving directions, the neighbouring block's vec4 for
// the one cell the x shift brings in (a vec4 fetch is plain loads on
// lavapipe; a float fetch is a gather, slower on AMD). At a wall the index
// simply points at the cell's own f*_O.
#define PULL(I, EX, EY, EZ)                                                                       \
  {                                                                                               \
    bool rowOutside = cellY - (EY) < 0 || cellY - (EY) >= NY || cellZ - (EZ) < 0 || cellZ - (EZ) >= NZ; \
    int from = LATTICE_INDEX(ownBlock - ((EY) * ROW + (EZ) * PLANE) / 4, EX, EY, EZ);             \
    int bounced = LATTICE_INDEX(ownBlock, -(EX), -(EY), -(EZ));                                   \
    const int nextBlock = GROUP_SIZE(ROW_GROUP(EY, EZ));                                          \
    vec4 c = texelFetch(lattice, rowOutside ? bounced : from);                                    \
    if ((EX) == 0) {                                                                              \
      f[I] = c;                                                                                   \
    } else if ((EX) == 1) {                                                                       \
      bool wall = rowOutside || firstInRow;                                                       \
      vec4 n = texelFetch(lattice, wall ? bounced : from - nextBlock);                            \
      f[I] = rowOutside ? c : vec4(wall ? n.x : n.w, c.xyz);                                      \
    } else {                                                                                      \
      bool wall = rowOutside || pastRowEnd.w;                                                     \
      vec4 n = texelFetch(lattice, wall ? bounced : from + nextBlock);                            \
      float right = wall ? n[lastLane] : n.x;                                                     \
      f[I] = rowOutside ? c : mix(vec4(c.yzw, right), vec4(right), pastRowEnd);                   \
    }                                                                                             \
  }

// Sets this invocation's block; false for invocations beyond the grid.
// Invocations run over the blocks of a z plane, row after row, so workgroups
// are full whatever the row length (a 70-cell row is 18 blocks).
bool locateBlock()
{
  const int blocksPerRow = ROW / 4;
  int index = int(gl_GlobalInvocationID.x);
  if (index >= blocksPerRow * NY) return false;
  int x0 = 4 * (index % blocksPerRow);
  cellY = index / blocksPerRow;
  cellZ = int(gl_WorkGroupID.z);
  ownBlock = linearIndex(ivec3(x0, cellY, cellZ)) / 4;
  firstInRow = x0 == 0;
  pastRowEnd = greaterThanEqual(ivec4(x0 + 1, x0 + 2, x0 + 3, x0 + 4), ivec4(NX));
  lastLane = min(NX - 1 - x0, 3);
  return true;
}

// X = sum_i f_i, and with a source X = (sum f + A/2) / (1 + c/2), S = A - c X:
// the second-order source treatment of docs/lattice-theory.md, solved exactly
// because S is linear in X. Summed in index order, as the CPU reference does.
// Written out rather than looped: a loop over the local array may be left
// rolled by the driver, and then f[] lives in scratch memory.
vec4 distributionSum()
{
  return f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8] + f[9] + f[10] + f[11] + f[12] + f[13] + f[14] +
         f[15] + f[16] + f[17] + f[18];
}
// X from that sum under a source of this decay c and scale k (A = k base).
vec4 fieldFromSum(vec4 sum, float decay, float baseScale, out vec4 S)
{
  vec4 X = sum;
  S = vec4(0.0);
  if (HAS_SOURCE) {
    vec4 A = baseScale * texelFetch(sourceBase, ownBlock);
    X = (X + 0.5 * A) / (1.0 + 0.5 * decay);
    S = A - decay * X;
  }
  return X;
}
vec4 fieldFromDistributions(out vec4 S) { return fieldFromSum(distributionSum(), params.decay, params.baseScale, S); }
