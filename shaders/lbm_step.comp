#version 450
#extension GL_GOOGLE_include_directive : require
// One lattice Boltzmann step: pull-streaming, then BGK collision towards
// f_eq = w_i X with the source share (1 - omega/2) w_i S, stored as the
// post-collision distributions for the next step.
#include "lattice.glsl"

// The next lattice copy, one binding per row group.
layout(set = 0, binding = 3, std430) writeonly buffer Distribution { vec4 cells[]; } nextGroup[GROUPS];

#define COLLIDE(I, W) \
  nextGroup[groupOf[I]].cells[indexInGroup(ownBlock, I)] = f[I] + omega * ((W) * X - f[I]) + sourceShare * (W) * S;

void main()
{
  if (!locateBlock()) return;
  PULL_ALL
  vec4 S;
  vec4 X = fieldFromDistributions(S);
  vec4 omega = PER_CELL_OMEGA ? texelFetch(omegaPerCell, ownBlock) : vec4(params.omega);
  vec4 sourceShare = 1.0 - 0.5 * omega;
  COLLIDE(0, W_REST)
  COLLIDE(1, W_AXIAL) COLLIDE(2, W_AXIAL) COLLIDE(3, W_AXIAL) COLLIDE(4, W_AXIAL) COLLIDE(5, W_AXIAL) COLLIDE(6, W_AXIAL)
  COLLIDE(7, W_DIAGONAL) COLLIDE(8, W_DIAGONAL) COLLIDE(9, W_DIAGONAL) COLLIDE(10, W_DIAGONAL)
  COLLIDE(11, W_DIAGONAL) COLLIDE(12, W_DIAGONAL) COLLIDE(13, W_DIAGONAL) COLLIDE(14, W_DIAGONAL)
  COLLIDE(15, W_DIAGONAL) COLLIDE(16, W_DIAGONAL) COLLIDE(17, W_DIAGONAL) COLLIDE(18, W_DIAGONAL)
}
