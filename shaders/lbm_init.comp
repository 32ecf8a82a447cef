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

#define INIT(J, EX, EY, EZ)                                                                      \
  {                                                                                              \
    ivec3 target = q + ivec3(EX, EY, EZ);                                                        \
    group[ROW_GROUP(EY, EZ)].cells[4 * INDEX_IN_GROUP(own / 4, EX, EY, EZ) + own % 4] =          \
        WEIGHT(EX, EY, EZ) * density.cells[isRealCell(target) ? linearIndex(target) : own];      \
  }

void main()
{
  ivec3 q = ivec3(gl_GlobalInvocationID);
  if (!isRealCell(q)) return;
  int own = linearIndex(q);
  FOR_EACH_DIRECTION(INIT)
}
