#version 450
#extension GL_GOOGLE_include_directive : require
// One lattice Boltzmann step: pull-streaming, then BGK collision towards
// f_eq = w_i X with the source share (1 - omega/2) w_i S, stored as the
// post-collision distributions for the next step.
#include "lattice.glsl"

layout(set = 0, binding = 4, std430) writeonly buffer Distribution { vec4 cells[]; } outVec4[19];

void main()
{
  if (!locateBlock()) return;
  vec4 f[19];
  PULL_ALL
  vec4 S;
  vec4 X = fieldFromDistributions(f, S);
  vec4 omega = PER_CELL_OMEGA ? texelFetch(omegaPerCell, ownBlock) : vec4(params.omega);
  vec4 sourceShare = 1.0 - 0.5 * omega;
  for (int i = 0; i < 19; ++i) {
    float w = i == 0 ? W_REST : (i <= 6 ? W_AXIAL : W_DIAGONAL);
    vec4 post = f[i] + omega * (w * X - f[i]) + sourceShare * w * S;
    // Constant indices after unrolling: no dynamic descriptor indexing needed.
    switch (i) {
      case 0: outVec4[0].cells[ownBlock] = post; break;
      case 1: outVec4[1].cells[ownBlock] = post; break;
      case 2: outVec4[2].cells[ownBlock] = post; break;
      case 3: outVec4[3].cells[ownBlock] = post; break;
      case 4: outVec4[4].cells[ownBlock] = post; break;
      case 5: outVec4[5].cells[ownBlock] = post; break;
      case 6: outVec4[6].cells[ownBlock] = post; break;
      case 7: outVec4[7].cells[ownBlock] = post; break;
      case 8: outVec4[8].cells[ownBlock] = post; break;
      case 9: outVec4[9].cells[ownBlock] = post; break;
      case 10: outVec4[10].cells[ownBlock] = post; break;
      case 11: outVec4[11].cells[ownBlock] = post; break;
      case 12: outVec4[12].cells[ownBlock] = post; break;
      case 13: outVec4[13].cells[ownBlock] = post; break;
      case 14: outVec4[14].cells[ownBlock] = post; break;
      case 15: outVec4[15].cells[ownBlock] = post; break;
      case 16: outVec4[16].cells[ownBlock] = post; break;
      case 17: outVec4[17].cells[ownBlock] = post; break;
      case 18: outVec4[18].cells[ownBlock] = post; break;
    }
  }
}
