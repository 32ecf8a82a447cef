#version 450
#extension GL_GOOGLE_include_directive : require
// Puts the lattice in equilibrium with a density field D: the next pull must
// deliver f_j(r) = w_j D(r). The value cell q stores for direction j is pulled
// by q + e_j, or, when q + e_j is outside, bounced back to q itself; so it is
// w_j D(q + e_j), or w_j D(q). Runs once per job, one cell per invocation.
#include "lattice_layout.glsl"

layout(local_size_x_id = 0) in;
layout(set = 0, binding = 0, std430) readonly buffer Density { float cells[]; } density;  // same layout
layout(set = 0, binding = 1, std430) writeonly buffer Distribution { float cells[]; } group[GROUPS];

#define INIT(J)                                                                                   \
  {                                                                                               \
    ivec3 target = q + velocity[J];                                                               \
    group[groupOf[J]].cells[4 * indexInGroup(own / 4, J) + own % 4] =                             \
        weight(J) * density.cells[isRealCell(target) ? linearIndex(target) : own];                \
  }

void main()
{
  ivec3 q = ivec3(gl_GlobalInvocationID);
  if (!isRealCell(q)) return;
  int own = linearIndex(q);
  INIT(0) INIT(1) INIT(2) INIT(3) INIT(4) INIT(5) INIT(6) INIT(7) INIT(8) INIT(9)
  INIT(10) INIT(11) INIT(12) INIT(13) INIT(14) INIT(15) INIT(16) INIT(17) INIT(18)
}
