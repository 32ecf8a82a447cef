// Shared by lbm_step.comp and lbm_field.comp: the lattice layout, the
// specialization constants the host sets (src/lbm/vulkan_solver.cpp) and the
// pull-streaming of the 19 distributions of four consecutive cells.
//
// Layout: structure of arrays, one buffer per direction, cells x-fastest with
// rows padded to ROW (a multiple of 4) so that cells x0..x0+3 (x0 % 4 == 0)
// are one vec4. Each invocation updates those four cells: lavapipe executes
// every buffer load and store one SIMD lane at a time, so fewer, wider memory
// instructions are what makes the step fast there.

layout(local_size_x_id = 0) in;
layout(constant_id = 1) const int NX = 4;   // cells along x
layout(constant_id = 2) const int NY = 1;
layout(constant_id = 3) const int NZ = 1;
layout(constant_id = 4) const int ROW = 4;  // padded row length, multiple of 4
layout(constant_id = 5) const float W_REST = 1.0 / 3.0;
layout(constant_id = 6) const float W_AXIAL = 1.0 / 18.0;
layout(constant_id = 7) const float W_DIAGONAL = 1.0 / 36.0;
layout(constant_id = 8) const bool PER_CELL_OMEGA = false;
layout(constant_id = 9) const bool HAS_SOURCE = false;

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

int blockX, cellY, cellZ, ownBlock;  // this invocation's four cells

// Pull-streaming of direction I with velocity (EX, EY, EZ) and opposite O into
// f[I]: each cell takes f*_I from its neighbour r - e_I; where that neighbour
// is outside the grid, the wall bounces back the cell's own f*_O (zero flux).
#define PULL(I, EX, EY, EZ, O)                                                              \
  {                                                                                         \
    int sy = cellY - (EY), sz = cellZ - (EZ);                                               \
    if (sy < 0 || sy >= NY || sz < 0 || sz >= NZ) {                                         \
      f[I] = texelFetch(inVec4[O], ownBlock);                                               \
    } else {                                                                                \
      int from = ownBlock - ((EY) + (EZ) * NY) * (ROW / 4);                                 \
      vec4 c = texelFetch(inVec4[I], from);                                                 \
      if ((EX) == 0) {                                                                      \
        f[I] = c;                                                                           \
      } else if ((EX) == 1) {                                                               \
        float left = blockX > 0 ? texelFetch(inScalar[I], 4 * from - 1).x                   \
                                : texelFetch(inScalar[O], 4 * ownBlock).x;                  \
        f[I] = vec4(left, c.xyz);                                                           \
      } else if (blockX + 4 < NX) {                                                         \
        f[I] = vec4(c.yzw, texelFetch(inScalar[I], 4 * from + 4).x);                        \
      } else {                                                                              \
        bvec4 outside = greaterThanEqual(ivec4(blockX + 1, blockX + 2, blockX + 3, blockX + 4), ivec4(NX)); \
        f[I] = mix(vec4(c.yzw, 0.0), texelFetch(inVec4[O], ownBlock), outside);             \
      }                                                                                     \
    }                                                                                       \
  }

// The velocities in the order of src/lbm/d3q19.hpp.
#define PULL_ALL                  \
  PULL(0, 0, 0, 0, 0)             \
  PULL(1, 1, 0, 0, 2)             \
  PULL(2, -1, 0, 0, 1)            \
  PULL(3, 0, 1, 0, 4)             \
  PULL(4, 0, -1, 0, 3)            \
  PULL(5, 0, 0, 1, 6)             \
  PULL(6, 0, 0, -1, 5)            \
  PULL(7, 1, 1, 0, 8)             \
  PULL(8, -1, -1, 0, 7)           \
  PULL(9, 1, -1, 0, 10)           \
  PULL(10, -1, 1, 0, 9)           \
  PULL(11, 1, 0, 1, 12)           \
  PULL(12, -1, 0, -1, 11)         \
  PULL(13, 1, 0, -1, 14)          \
  PULL(14, -1, 0, 1, 13)          \
  PULL(15, 0, 1, 1, 16)           \
  PULL(16, 0, -1, -1, 15)         \
  PULL(17, 0, 1, -1, 18)          \
  PULL(18, 0, -1, 1, 17)

// Sets this invocation's cells; false for invocations past the row's end.
bool locateBlock()
{
  blockX = 4 * int(gl_GlobalInvocationID.x);
  cellY = int(gl_GlobalInvocationID.y);
  cellZ = int(gl_GlobalInvocationID.z);
  ownBlock = (blockX + ROW * (cellY + NY * cellZ)) / 4;
  return blockX < NX;
}

// X = sum_i f_i, and with a source X = (sum f + A/2) / (1 + c/2), S = A - c X:
// the second-order source treatment of docs/lattice-theory.md, solved exactly
// because S is linear in X. Summed in index order, as the CPU reference does.
vec4 fieldFromDistributions(vec4 f[19], out vec4 S)
{
  vec4 X = f[0];
  for (int i = 1; i < 19; ++i) X += f[i];
  S = vec4(0.0);
  if (HAS_SOURCE) {
    vec4 A = texelFetch(sourceBase, ownBlock);
    X = (X + 0.5 * A) / (1.0 + 0.5 * params.decay);
    S = A - params.decay * X;
  }
  return X;
}
