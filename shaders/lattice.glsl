// Shared by lbm_step.comp and lbm_field.comp: the bindings they read and the
// pull-streaming of the 19 distributions of four consecutive cells.
//
// Each invocation updates cells x0..x0+3 of one row. Lavapipe executes every
// buffer load and store one SIMD lane at a time, so fewer, wider memory
// instructions and no divergent branches are what make the step fast there.

#include "lattice_layout.glsl"

layout(local_size_x_id = 0, local_size_y_id = 1) in;
layout(constant_id = 9) const bool PER_CELL_OMEGA = false;
layout(constant_id = 10) const bool HAS_SOURCE = false;


layout(push_constant) uniform StepParameters {
  float omega;  // 1/tau where it is the same in every cell
  float decay;  // c in the source S = A - c X
} params;

// Post-collision distributions of the previous step, read as vec4 (four
// cells) and as float (for the one neighbour outside the vec4 that the
// x-moving directions need). Both views cover the same buffers.
layout(set = 0, binding = 0) uniform samplerBuffer inVec4[19];
layout(set = 0, binding = 1) uniform samplerBuffer inScalar[19];
layout(set = 0, binding = 2) uniform samplerBuffer omegaPerCell;  // 1/tau per cell
layout(set = 0, binding = 3) uniform samplerBuffer sourceBase;    // A per cell

int ownBlock;       // vec4 index of this invocation's four cells
bool firstInRow;    // cell x0 is at the x = 0 wall
bvec4 pastRowEnd;   // per lane: the upstream neighbour along -x is beyond x = NX - 1
int lastLane;       // the lane of cell NX - 1 if it is in this block
vec4 f[19];         // the four cells' distributions after streaming

// f[I] = f*_I(r - e_I) for the four cells: one vec4 fetch from the upstream
// row, plus one float for the cell that the x shift brings in. Walls in y and
// z are ghost rows (lbm_halo.comp fills them). The walls in x are handled in
// the pull, without branches: where the upstream neighbour is outside, the
// lane selects the cell's own f*_O, which the wall bounces back. Lavapipe runs
// divergent branches with both sides masked, so selecting is cheaper than
// branching; and every extra fetch is paid by every block, so the x walls
// cost as few as possible: the +-x directions reuse the own-row vec4s that
// they fetch anyway, and a diagonal fetches one float.

// Directions with e_x = 0.
#define PULL_STRAIGHT(I, EY, EZ) f[I] = texelFetch(inVec4[I], ownBlock - ((EY) * ROW + (EZ) * PLANE) / 4);

// Diagonals with e_x = +1: lane 0 of the first block takes the wall's value.
#define PULL_FROM_LEFT(I, EY, EZ, O)                                          \
  {                                                                           \
    int from = ownBlock - ((EY) * ROW + (EZ) * PLANE) / 4;                    \
    vec4 c = texelFetch(inVec4[I], from);                                     \
    float left = texelFetch(inScalar[I], 4 * from - 1).x;                     \
    float wall = texelFetch(inScalar[O], 4 * ownBlock).x;                     \
    f[I] = vec4(firstInRow ? wall : left, c.xyz);                             \
  }

// Diagonals with e_x = -1: the lane of cell NX - 1 takes the wall's value
// (lanes beyond it are padding, whatever they get).
#define PULL_FROM_RIGHT(I, EY, EZ, O)                                         \
  {                                                                           \
    int from = ownBlock - ((EY) * ROW + (EZ) * PLANE) / 4;                    \
    vec4 c = texelFetch(inVec4[I], from);                                     \
    float right = texelFetch(inScalar[I], 4 * from + 4).x;                    \
    float wall = texelFetch(inScalar[O], 4 * ownBlock + lastLane).x;          \
    f[I] = mix(vec4(c.yzw, right), vec4(wall), pastRowEnd);                   \
  }

#define PULL_ALL                                                                          \
  PULL_STRAIGHT(0, 0, 0)                                                                  \
  {                                                                                       \
    vec4 own1 = texelFetch(inVec4[1], ownBlock), own2 = texelFetch(inVec4[2], ownBlock);  \
    float left = texelFetch(inScalar[1], 4 * ownBlock - 1).x;                             \
    float right = texelFetch(inScalar[2], 4 * ownBlock + 4).x;                            \
    f[1] = vec4(firstInRow ? own2.x : left, own1.xyz);                                    \
    f[2] = mix(vec4(own2.yzw, right), own1, pastRowEnd);                                  \
  }                                                                                       \
  PULL_STRAIGHT(3, 1, 0) PULL_STRAIGHT(4, -1, 0) PULL_STRAIGHT(5, 0, 1) PULL_STRAIGHT(6, 0, -1) \
  PULL_FROM_LEFT(7, 1, 0, 8) PULL_FROM_RIGHT(8, -1, 0, 7)                                 \
  PULL_FROM_LEFT(9, -1, 0, 10) PULL_FROM_RIGHT(10, 1, 0, 9)                               \
  PULL_FROM_LEFT(11, 0, 1, 12) PULL_FROM_RIGHT(12, 0, -1, 11)                             \
  PULL_FROM_LEFT(13, 0, -1, 14) PULL_FROM_RIGHT(14, 0, 1, 13)                             \
  PULL_STRAIGHT(15, 1, 1) PULL_STRAIGHT(16, -1, -1) PULL_STRAIGHT(17, 1, -1) PULL_STRAIGHT(18, -1, 1)

// Sets this invocation's block; false for invocations beyond the grid.
bool locateBlock()
{
  ivec3 id = ivec3(gl_GlobalInvocationID);
  int x0 = 4 * id.x;
  if (x0 >= NX || id.y >= NY) return false;
  ownBlock = linearIndex(ivec3(x0, id.yz)) / 4;
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
vec4 fieldFromDistributions(out vec4 S)
{
  vec4 X = f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8] + f[9] + f[10] + f[11] + f[12] + f[13] +
           f[14] + f[15] + f[16] + f[17] + f[18];
  S = vec4(0.0);
  if (HAS_SOURCE) {
    vec4 A = texelFetch(sourceBase, ownBlock);
    X = (X + 0.5 * A) / (1.0 + 0.5 * params.decay);
    S = A - params.decay * X;
  }
  return X;
}
