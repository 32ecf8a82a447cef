#version 450
#extension GL_GOOGLE_include_directive : require
// lbmshape's feature-preserving rule on the narrow band, from the field that
// band_step.comp's BAND_PASS_FIELD_TO_OLDER stored in moment 0 of the older
// copy of the moments, dispatched with the descriptor set that reads that
// copy: omega per stored cell into the omega buffer. No scratch buffer, and
// nothing goes back to the host.
//
// A pipeline of its own, not a pass of band_step.comp: lavapipe runs a
// branch on a push constant with both sides masked, so as a pass the rule
// cost more than a whole step (320 ms at --res 512), and every step paid for
// the rule's code.
#include "band_rows.glsl"
#include "feature_rule.glsl"

// Row (y + dy, z + dz) of X from moment 0 of the copy this dispatch reads
// (where BAND_PASS_FIELD_TO_OLDER put it), as cells 0-3 and 4-7, placed by
// rowPlace(): the own row beyond the grid's faces (zero flux: a neighbour
// there reads as the cell itself, as on the CPU) and in a brick outside the
// band. The CPU reads the far value there instead:
// only cells at the band's edge have such a neighbour, and they never
// stream (a streaming cell has its 18 lattice neighbours in the band), so
// their flux j* starts at 0 and stays 0 whatever omega they get: the steps
// come out the same.
void fieldRow(int dy, int dz, out vec4 a, out vec4 b)
{
  const RowPlace row = rowPlace(y + dy, z + dz);
  a = moment(momentAt(row.slot, 0, row.ly, row.lz, 0));
  b = moment(momentAt(row.slot, 0, row.ly, row.lz, 1));
}

// lbmshape's feature-preserving rule (feature_rule.glsl) for the row's
// eight cells, kappa the 7-point Laplacian of X: omega into the omega
// buffer. Cells beyond the grid (in bricks at its far faces) get gamma0's.
void featureRule()
{
  vec4 ownA, ownB, downA, downB, upA, upB, backA, backB, frontA, frontB;
  fieldRow(0, 0, ownA, ownB);
  fieldRow(-1, 0, downA, downB);
  fieldRow(1, 0, upA, upB);
  fieldRow(0, -1, backA, backB);
  fieldRow(0, 1, frontA, frontB);
  // Along x: the cells beside the row's ends from the bricks beside it.
  const ivec3 bricks = rowBricks(0, 0);
  const int leftSlot = bricks.x, rightSlot = bricks.z;
  const float left = origin.x > 0 && leftSlot >= 0 ? moment(momentAt(leftSlot, 0, y, z, 1)).w : ownA.x;
  const float right = rightSlot >= 0 ? moment(momentAt(rightSlot, 0, y, z, 0)).x : ownB.w;
  const vec4 leftA = vec4(left, ownA.xyz), leftB = vec4(ownA.w, ownB.xyz);
  vec4 rightA = vec4(ownA.yzw, ownB.x), rightB = vec4(ownB.yzw, right);
  // A cell at the grid's last x reads itself as its right neighbour.
  rightA = mix(rightA, ownA, greaterThanEqual(origin.x + ivec4(1, 2, 3, 4), ivec4(p.nx)));
  rightB = mix(rightB, ownB, greaterThanEqual(origin.x + ivec4(5, 6, 7, 8), ivec4(p.nx)));
  const vec4 kappaA = leftA + rightA + downA + upA + backA + frontA - 6.0 * ownA;
  const vec4 kappaB = leftB + rightB + downB + upB + backB + frontB - 6.0 * ownB;
  const bool rowInGrid = origin.y + y < p.ny && origin.z + z < p.nz;
  const bvec4 insideA = both(bvec4(rowInGrid), lessThan(origin.x + ivec4(0, 1, 2, 3), ivec4(p.nx)));
  const bvec4 insideB = both(bvec4(rowInGrid), lessThan(origin.x + ivec4(4, 5, 6, 7), ivec4(p.nx)));
  const int cells = (slot * 64 + z * 8 + y) * 2;  // vec4 index in the per-cell arrays
  storePerCell(cells, featurePreservingOmega(kappaA, not(insideA), p.gamma0, p.kappaEdge, p.lowestGamma));
  storePerCell(cells + 1, featurePreservingOmega(kappaB, not(insideB), p.gamma0, p.kappaEdge, p.lowestGamma));
}

void main()
{
  if (locateRow()) featureRule();
}
