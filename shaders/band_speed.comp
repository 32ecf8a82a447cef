#version 450
#extension GL_GOOGLE_include_directive : require
// The surface's speed between the narrow band's last two steps, measured
// where the lattice is: --steps auto reads a vec4 a row of eight cells
// after each step instead of the whole band (pipeline/smoothing_stop.hpp
// has the rule, lbm/surface_change.hpp the same sums on the CPU). A
// workgroup is one brick, an invocation one of its rows; each row's sums
// (of the change, of its square, and its cells) go to its own vec4 of the
// partials, which the host adds up in double (SurfaceChangeSums). No
// reduction in the workgroup: on lavapipe its six barriers made the pass a
// third of a step (1.7 ms at --res 128, now 0.6 ms).
#include "band_interface.h"

layout(local_size_x = BAND_WORKGROUP_SIZE) in;
layout(push_constant) uniform Parameters { BAND_SPEED_PARAMETERS(BAND_DECLARE_FIELD) } p;

layout(set = 0, binding = BAND_SPEED_BINDING_NEWER) uniform samplerBuffer newer;
layout(set = 0, binding = BAND_SPEED_BINDING_OLDER) uniform samplerBuffer older;
layout(set = 0, binding = BAND_SPEED_BINDING_PARTIALS, std430) writeonly buffer Partials { vec4 partials[]; };

void main()
{
  const int slot = int(gl_WorkGroupID.x + gl_WorkGroupID.y * BAND_MAX_WORKGROUPS_X);
  if (slot >= p.slots) return;
  const int row = int(gl_LocalInvocationID.x);
  vec3 sums = vec3(0.0);  // change, its square, cells
  for (int part = 0; part < 2; ++part) {  // cells 0-3, then 4-7
    const int index = BAND_MOMENT_INDEX(slot, 0, row, part);
    const vec4 before = texelFetch(older, index);
    const vec4 after = texelFetch(newer, index);
    const vec4 onSurface = vec4(lessThan(abs(before), vec4(1.0)));
    const vec4 change = onSurface * (after - before);
    sums += vec3(dot(change, vec4(1.0)), dot(change, change), dot(onSurface, vec4(1.0)));
  }
  partials[slot * BAND_WORKGROUP_SIZE + row] = vec4(sums, 0.0);
}
