#version 450
#extension GL_GOOGLE_include_directive : require
// Zero-flux walls in y and z by bounce-back, after each step: for every cell r
// on a y or z face of the grid and every direction i that crosses that face
// inwards, the ghost slot r - e_i of direction i gets f*_opp(i)(r), which the
// next pull then delivers to r. Workgroup layer z picks the face, so every
// branch here is uniform; each invocation handles one block of four cells and
// exactly the five directions that cross its face. Only ghost rows are
// written; where two faces meet, both write the same values to the same slots.
// (The x walls need no ghosts: see lattice.glsl.)
#include "lattice_layout.glsl"

layout(local_size_x_id = 0) in;
layout(set = 0, binding = 0) uniform samplerBuffer inVec4[19];    // the lattice just written,
layout(set = 0, binding = 1) uniform samplerBuffer inScalar[19];  // read as in lattice.glsl
layout(set = 0, binding = 2, std430) writeonly buffer Distribution { vec4 cells[]; } outVec4[19];

// One invocation handles four cells x0..x0+3 of a face row and writes, per
// direction, one aligned vec4 of the ghost row: slots x0..x0+3 take f*_O of
// the face cells x0 + e_x .. x0 + 3 + e_x. (Ghost slots that only a cell
// beyond the x walls would read get whatever lies there; the x walls never
// read ghosts.)
int own, x0;
ivec3 faceRow;  // (x0, y, z) of the face cells

// I: direction, (EX, EY, EZ) its velocity, O its opposite. Literal indices
// keep every descriptor array index a compile-time constant.
#define BOUNCE(I, EX, EY, EZ, O)                                                        \
  {                                                                                     \
    vec4 c = texelFetch(inVec4[O], own);                                                \
    vec4 v = (EX) == 0 ? c                                                              \
           : (EX) == 1 ? vec4(c.yzw, texelFetch(inScalar[O], 4 * own + 4).x)            \
                       : vec4(texelFetch(inScalar[O], 4 * own - 1).x, c.xyz);           \
    outVec4[I].cells[linearIndex(faceRow - ivec3(0, EY, EZ)) / 4] = v;                  \
  }

void main()
{
  const int face = int(gl_WorkGroupID.z);  // 0/1: z = 0 / NZ-1, 2/3: y = 0 / NY-1
  const int blocksPerRow = (NX + 3) / 4;
  const int k = int(gl_GlobalInvocationID.x);
  const int rows = face < 2 ? NY : NZ;
  if (k >= blocksPerRow * rows) return;
  x0 = 4 * (k % blocksPerRow);
  if (face < 2) faceRow = ivec3(x0, k / blocksPerRow, face == 0 ? 0 : NZ - 1);
  else faceRow = ivec3(x0, face == 2 ? 0 : NY - 1, k / blocksPerRow);
  own = linearIndex(faceRow) / 4;
  switch (face) {
    case 0:  // e_z = +1
      BOUNCE(5, 0, 0, 1, 6) BOUNCE(11, 1, 0, 1, 12) BOUNCE(14, -1, 0, 1, 13) BOUNCE(15, 0, 1, 1, 16) BOUNCE(18, 0, -1, 1, 17)
      break;
    case 1:  // e_z = -1
      BOUNCE(6, 0, 0, -1, 5) BOUNCE(12, -1, 0, -1, 11) BOUNCE(13, 1, 0, -1, 14) BOUNCE(16, 0, -1, -1, 15) BOUNCE(17, 0, 1, -1, 18)
      break;
    case 2:  // e_y = +1
      BOUNCE(3, 0, 1, 0, 4) BOUNCE(7, 1, 1, 0, 8) BOUNCE(10, -1, 1, 0, 9) BOUNCE(15, 0, 1, 1, 16) BOUNCE(17, 0, 1, -1, 18)
      break;
    default:  // e_y = -1
      BOUNCE(4, 0, -1, 0, 3) BOUNCE(8, -1, -1, 0, 7) BOUNCE(9, 1, -1, 0, 10) BOUNCE(16, 0, -1, -1, 15) BOUNCE(18, 0, -1, 1, 17)
      break;
  }
}
