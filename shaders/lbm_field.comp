#version 450
#extension GL_GOOGLE_include_directive : require
// The field X of the current state: the same pull and sum as a step, without
// the collision, written to the field buffer.
#include "lattice.glsl"

layout(set = 0, binding = LATTICE_BINDING_FIELD, std430) writeonly buffer Field { vec4 cells[]; } fieldOut;

void main()
{
  if (!locateBlock()) return;
  FOR_EACH_DIRECTION(PULL)
  vec4 S;
  fieldOut.cells[ownBlock] = fieldFromDistributions(S);
}
