#version 450
#extension GL_GOOGLE_include_directive : require
// Puts the lattice in equilibrium with a density field D: the next pull must
// deliver f_j(r) = w_j D(r). So every slot q (ghosts included) of direction j
// holds w_j D(q + e_j) when q + e_j is a real cell; a real cell q whose
// q + e_j is outside holds w_j D(q), which the wall bounces back to q itself
// (directly in x, through the ghost rows in y and z). Runs once per job, over
// the whole padded volume, one slot per invocation. A padding slot can stand
// for two ghosts (x = NX of its row and x = -1 of the next), but for any one
// direction at most one of them feeds a real cell, so only that one writes.
#include "lattice_layout.glsl"

layout(local_size_x_id = 0) in;
layout(set = 0, binding = 0, std430) readonly buffer Density { float cells[]; } density;  // same layout
layout(set = 0, binding = 1, std430) writeonly buffer Distribution { float cells[]; } lattice[19];

#define INIT(J)                                                                          \
  {                                                                                      \
    ivec3 target = q + velocity[J];                                                      \
    if (isRealCell(target)) lattice[J].cells[slot] = weight(J) * density.cells[linearIndex(target)]; \
    else if (isRealCell(q)) lattice[J].cells[slot] = weight(J) * density.cells[slot];                \
  }

void main()
{
  ivec3 q = ivec3(gl_GlobalInvocationID) - ivec3(1);
  if (q.x > ROW - 1 || q.y > NY || q.z > NZ) return;
  int slot = linearIndex(q);
  INIT(0) INIT(1) INIT(2) INIT(3) INIT(4) INIT(5) INIT(6) INIT(7) INIT(8) INIT(9)
  INIT(10) INIT(11) INIT(12) INIT(13) INIT(14) INIT(15) INIT(16) INIT(17) INIT(18)
}
