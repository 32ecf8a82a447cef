#version 450
#extension GL_GOOGLE_include_directive : require
// One lattice Boltzmann step: pull-streaming, then BGK collision towards
// f_eq = w_i X with the source share (1 - omega/2) w_i S, stored as the
// post-collision distributions for the next step.
#include "lattice.glsl"

// The next lattice copy, one binding per row group.
layout(set = 0, binding = 3, std430) writeonly buffer Distribution { vec4 cells[]; } nextGroup[GROUPS];

#define COLLIDE(I, EX, EY, EZ)                                                                   \
  nextGroup[ROW_GROUP(EY, EZ)].cells[INDEX_IN_GROUP(ownBlock, EX, EY, EZ)] =                     \
      f[I] + omega * (WEIGHT(EX, EY, EZ) * X - f[I]) + sourceShare * WEIGHT(EX, EY, EZ) * S;

void main()
{
  if (!locateBlock()) return;
  FOR_EACH_DIRECTION(PULL)
  vec4 S;
  vec4 X = fieldFromDistributions(S);
  vec4 omega = PER_CELL_OMEGA ? texelFetch(omegaPerCell, ownBlock) : vec4(params.omega);
  vec4 sourceShare = 1.0 - 0.5 * omega;
  FOR_EACH_DIRECTION(COLLIDE)
}
