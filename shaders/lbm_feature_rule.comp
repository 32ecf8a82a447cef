#version 450
#extension GL_GOOGLE_include_directive : require
// lbmshape's feature-preserving rule (feature_rule.glsl) on the dense
// lattice, from the field that the field pass left in the field buffer:
// kappa the 7-point Laplacian of X (a neighbour beyond the grid's faces
// reads as the cell itself: zero flux), omega per cell into the omega
// buffer, which the steps read from then on. Nothing goes to the host and
// back.
//
// An invocation is one block of four cells of a row, as in the field pass;
// the padding beyond a row's end gets gamma0.
#include "lattice_layout.glsl"
#include "lattice_interface.h"
#include "feature_rule.glsl"

layout(local_size_x_id = 0) in;
layout(push_constant) uniform RuleParameters { LATTICE_FEATURE_RULE_PARAMETERS(LATTICE_DECLARE_FIELD) } p;
layout(set = 0, binding = LATTICE_BINDING_FIELD, std430) readonly buffer Field { vec4 cells[]; } field;
layout(set = 0, binding = LATTICE_BINDING_GAMMA, std430) writeonly buffer Omega { vec4 cells[]; } omegaOut;

void main()
{
  const int blocksPerRow = ROW / 4;
  const int index = int(gl_GlobalInvocationID.x);
  if (index >= blocksPerRow * NY) return;
  const int x0 = 4 * (index % blocksPerRow), y = index / blocksPerRow, z = int(gl_WorkGroupID.z);
  const int own = linearIndex(ivec3(x0, y, z)) / 4;
  const vec4 X = field.cells[own];
  const vec4 down = field.cells[y > 0 ? own - ROW / 4 : own];
  const vec4 up = field.cells[y < NY - 1 ? own + ROW / 4 : own];
  const vec4 back = field.cells[z > 0 ? own - PLANE / 4 : own];
  const vec4 front = field.cells[z < NZ - 1 ? own + PLANE / 4 : own];
  // Along x: the cells beside the block's ends from the blocks beside it.
  const float left = x0 > 0 ? field.cells[own - 1].w : X.x;
  const float right = x0 + 4 < NX ? field.cells[own + 1].x : X.w;
  // A cell at the grid's last x reads itself as its right neighbour.
  const bvec4 lastOrPast = greaterThanEqual(ivec4(x0) + ivec4(1, 2, 3, 4), ivec4(NX));
  const vec4 rightX = mix(vec4(X.yzw, right), X, lastOrPast);
  const vec4 leftX = vec4(left, X.xyz);
  const vec4 kappa = leftX + rightX + down + up + back + front - 6.0 * X;
  const bvec4 past = greaterThanEqual(ivec4(x0) + ivec4(0, 1, 2, 3), ivec4(NX));
  omegaOut.cells[own] = featurePreservingOmega(kappa, past, p.gamma0, p.kappaEdge, p.lowestGamma);
}
