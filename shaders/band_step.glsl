// One step of the narrow-band lattice in moment form (src/lbm/band_solver.hpp
// has the scheme; band_reference_solver.cpp is the same arithmetic on the
// CPU): pull f_i = w_i (rho* + 3 e_i . j*) from the upstream cell, sum X and
// J, apply the source, collide and store (rho*, j*). With the push constant
// `pass` BAND_PASS_FIELD or BAND_PASS_FIELD_TO_OLDER it stores X instead:
// the field of the current state (band_feature_rule.comp turns the latter
// into omega per cell); with `writeField` a step stores that X as well.
//
// With PAPER_RULE the relaxation is the paper's anisotropic rule (section
// 5.1, Eq. 20), as in lbm_step.comp: a cell collides with
// gamma = clamp(gamma0 + (X - rho*) / gamma before), rho* being the X its
// last step pulled (no source runs with the rule), and keeps that gamma.
//
// A workgroup is one brick (band_rows.glsl); an invocation one of its rows
// of eight cells, as two vec4 per moment, so every fetch brings four cells
// (on lavapipe a vec4 texel fetch is plain loads, other loads one lane at a
// time) and only the cells beyond the row's ends come from the bricks
// beside it. On lavapipe a step's time is mostly its fetches, lane by lane:
// each of the nine rows around is fetched once for the velocities that
// pull from it, and the bricks a row and its ends lie in come in one fetch.
//
// band_step.comp compiles it as it is; band_hold.comp with BAND_HOLD_ONLY,
// for the bricks held whole (BandSolver::setHeldBricks): every cell pulls
// from itself, and nothing is read from any other cell, where band_step
// would fetch every neighbour's row whether it uses it or not (lavapipe
// pays for a fetch under a branch as if it were taken).
#include "adaptive_gamma_bounds.h"
#include "band_rows.glsl"

layout(constant_id = BAND_SPEC_W_REST) const float W_REST = 1.0 / 3.0;
layout(constant_id = BAND_SPEC_W_AXIAL) const float W_AXIAL = 1.0 / 18.0;
layout(constant_id = BAND_SPEC_W_DIAGONAL) const float W_DIAGONAL = 1.0 / 36.0;

// What changes within a run is a push constant: per-cell omega (a denoise
// finds its edges with a uniform omega first), the pass and writeField. What
// sets a run's kind, the morph's source and the paper's rule, is a
// specialization constant: one pipeline a run (lavapipe spends about 100 ms
// creating each), and lavapipe, which runs both sides of a branch on a push
// constant (masked), no longer pays for the source's and the rule's fetches
// and stores in every denoise step (7 % of a step at 512^3).
layout(constant_id = BAND_SPEC_HAS_SOURCE) const bool HAS_SOURCE = false;
layout(constant_id = BAND_SPEC_PAPER_RULE) const bool PAPER_RULE = false;
#define PER_CELL_OMEGA (p.perCellOmega != 0)

layout(set = 0, binding = BAND_BINDING_STREAMS) uniform usamplerBuffer streamBits;
layout(set = 0, binding = BAND_BINDING_OMEGA) uniform samplerBuffer omegaPerCell;
layout(set = 0, binding = BAND_BINDING_SOURCE) uniform samplerBuffer sourceBase;
layout(set = 0, binding = BAND_BINDING_NEXT, std430) writeonly buffer NextPool { vec4 v[]; } nextPools[BAND_MAX_POOLS];
layout(set = 0, binding = BAND_BINDING_FIELD, std430) writeonly buffer FieldPool { vec4 v[]; } fieldPools[BAND_MAX_FIELD_POOLS];

vec4 fa[19], fb[19];  // the row's cells 0-3 and 4-7, pulled
vec4 ownA[4], ownB[4];  // the same cells' own moments

#define WEIGHT(EX, EY, EZ) \
  ((EX) * (EX) + (EY) * (EY) + (EZ) * (EZ) == 0 ? W_REST : (EX) * (EX) + (EY) * (EY) + (EZ) * (EZ) == 1 ? W_AXIAL : W_DIAGONAL)
// e . j for a velocity of literal components, without multiplications by 0
// (so the sum is the CPU reference's, term for term).
#define E_DOT(EX, EY, EZ, JX, JY, JZ)                                                      \
  (((EX) == 0 ? vec4(0.0) : float(EX) * (JX)) + ((EY) == 0 ? vec4(0.0) : float(EY) * (JY)) + \
   ((EZ) == 0 ? vec4(0.0) : float(EZ) * (JZ)))

// The row (y - EY, z - EZ) that some of the row's cells pull from, possibly
// in a neighbouring brick, fetched once for all the velocities that pull
// from it (nine rows for nineteen velocities: lavapipe does not merge the
// repeated fetches itself): its moments ra (cells 0-3) and rb (4-7), and with
// LEFT and RIGHT the moments of the cells beyond its ends, from the bricks
// beside it. `valid` false where the row is beyond the grid's faces or in a
// brick outside the band; then the invocation's own row stands in for it.
#define FETCH_ROW(EY, EZ, LEFT, RIGHT)                                                       \
  const RowPlace row = rowPlace(y - (EY), z - (EZ));                                         \
  vec4 ra[4], rb[4];                                                                         \
  for (int k = 0; k < 4; ++k) {                                                              \
    ra[k] = moment(momentAt(row.slot, k, row.ly, row.lz, 0));                                \
    rb[k] = moment(momentAt(row.slot, k, row.ly, row.lz, 1));                                \
  }                                                                                          \
  FETCH_ENDS(LEFT, RIGHT)

// The row's own cells (the rest velocity and the two along x).
#define OWN_ROW(LEFT, RIGHT)                                                                 \
  RowPlace row;                                                                              \
  const ivec3 bricks = rowBricks(0, 0);                                                      \
  row.slot = slot, row.ly = y, row.lz = z, row.left = bricks.x, row.right = bricks.z;        \
  row.valid = true;                                                                          \
  vec4 ra[4] = ownA, rb[4] = ownB;                                                           \
  FETCH_ENDS(LEFT, RIGHT)

#define FETCH_ENDS(LEFT, RIGHT)                                                              \
  float left[4], right[4];                                                                   \
  bool leftValid = false, rightValid = false;                                                \
  if (LEFT) {                                                                                \
    leftValid = row.valid && origin.x > 0 && row.left >= 0;                                  \
    for (int k = 0; k < 4; ++k) left[k] = moment(momentAt(leftValid ? row.left : row.slot, k, row.ly, row.lz, 1)).w; \
  }                                                                                          \
  if (RIGHT) {                                                                               \
    rightValid = row.valid && row.right >= 0;                                                \
    for (int k = 0; k < 4; ++k) right[k] = moment(momentAt(rightValid ? row.right : row.slot, k, row.ly, row.lz, 0)).x; \
  }

// fa[I], fb[I]: the row's eight cells pull from the cells at -e_I, in the
// row fetched last (FETCH_ROW), shifted by one cell along x for EX != 0 (the
// cell beyond the row's end from the neighbouring brick). A cell whose
// upstream cell is outside the grid (or, never for a streaming cell,
// outside the band) bounces back: f*_opposite of itself. (A cell that does
// not stream pulls from itself: finish() drops what it pulled here.)
#define PULL(I, EX, EY, EZ)                                                                                    \
  {                                                                                                            \
    vec4 a[4] = ra, b[4] = rb;                                                                                 \
    bvec4 validA = bvec4(row.valid), validB = bvec4(row.valid);                                                \
    if ((EX) == 1) {                                                                                           \
      for (int k = 0; k < 4; ++k) {                                                                            \
        b[k] = vec4(ra[k].w, rb[k].xyz);                                                                       \
        a[k] = vec4(left[k], ra[k].xyz);                                                                       \
      }                                                                                                        \
      validA.x = leftValid;                                                                                    \
    } else if ((EX) == -1) {                                                                                   \
      for (int k = 0; k < 4; ++k) {                                                                            \
        a[k] = vec4(ra[k].yzw, rb[k].x);                                                                       \
        b[k] = vec4(rb[k].yzw, right[k]);                                                                      \
      }                                                                                                        \
      validA = both(validA, lessThan(origin.x + ivec4(1, 2, 3, 4), ivec4(p.nx)));                              \
      validB = both(validB, lessThan(origin.x + ivec4(5, 6, 7, 8), ivec4(p.nx)));                              \
      validB.w = validB.w && rightValid;                                                                       \
    }                                                                                                          \
    const float w = WEIGHT(EX, EY, EZ);                                                                        \
    /* at a wall: the cell's own f*_opposite, w (rho* - 3 e . j*) */                                         \
    fa[I] = mix(w * (ownA[0] - 3.0 * E_DOT(EX, EY, EZ, ownA[1], ownA[2], ownA[3])),                            \
                w * (a[0] + 3.0 * E_DOT(EX, EY, EZ, a[1], a[2], a[3])), validA);                               \
    fb[I] = mix(w * (ownB[0] - 3.0 * E_DOT(EX, EY, EZ, ownB[1], ownB[2], ownB[3])),                            \
                w * (b[0] + 3.0 * E_DOT(EX, EY, EZ, b[1], b[2], b[3])), validB);                               \
  }

// X from the sum of the pulled f under a source of decay c and scale k:
// X = (sum + A/2) / (1 + c/2), A = k base, S = A - c X (lattice.glsl's
// fieldFromSum; without a source X is the sum).
vec4 fieldFromSum(vec4 sum, float decay, float baseScale, int cells, out vec4 S)
{
  S = vec4(0.0);
  if (!HAS_SOURCE) return sum;
  const vec4 A = baseScale * texelFetch(sourceBase, cells);
  const vec4 X = (sum + 0.5 * A) / (1.0 + 0.5 * decay);
  S = A - decay * X;
  return X;
}

// X = sum f, J = sum e f (in index order, as the CPU reference sums), the
// source, then the collision or the field, for one half of the row. A cell
// that does not stream pulls from itself, f_i = w_i (rho* + 3 e_i . j*):
// those sum to rho* and their flux is j*, taken as they are (the f it
// pulled from its neighbours are dropped).
void collide(vec4 sum, vec4 Jx, vec4 Jy, vec4 Jz, vec4 rhoBefore, int part);

void finish(vec4 f[19], vec4 own[4], bvec4 streams, int part)
{
  const vec4 sum = f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8] + f[9] + f[10] + f[11] + f[12] +
                   f[13] + f[14] + f[15] + f[16] + f[17] + f[18];
  const vec4 Jx = f[1] - f[2] + f[7] - f[8] + f[9] - f[10] + f[11] - f[12] + f[13] - f[14];
  const vec4 Jy = f[3] - f[4] + f[7] - f[8] - f[9] + f[10] + f[15] - f[16] + f[17] - f[18];
  const vec4 Jz = f[5] - f[6] + f[11] - f[12] - f[13] + f[14] + f[15] - f[16] - f[17] + f[18];
  collide(mix(own[0], sum, streams), mix(own[1], Jx, streams), mix(own[2], Jy, streams), mix(own[3], Jz, streams),
          own[0], part);
}

// The rest of a step (or the field) for one half of the row, from the sum of
// its pulled f and their flux.
void collide(vec4 sum, vec4 Jx, vec4 Jy, vec4 Jz, vec4 rhoBefore, int part)
{
  const int cells = (slot * 64 + z * 8 + y) * 2 + part;  // vec4 index in the per-cell arrays
  vec4 S;
  const vec4 X = fieldFromSum(sum, p.decay, p.baseScale, cells, S);
  // Every pool holds whole bricks, so a workgroup writes to one pool: the
  // pool index is the same across it (dynamically uniform).
  if (p.pass == BAND_PASS_FIELD || p.writeField != 0) {
    // A step's own field, for a frame, is that of the state it starts from
    // under the source of the steps before (a morph may raise Cs from this
    // step on): what the field pass would store.
    vec4 unused;
    const vec4 field = p.writeField != 0 ? fieldFromSum(sum, p.fieldDecay, p.fieldBaseScale, cells, unused) : X;
    fieldPools[perCellPool()].v[inPerCellPool(cells)] = field;
    if (p.pass == BAND_PASS_FIELD) return;
  }
  const int pool = slot / p.slotsPerMomentPool, first = slot - pool * p.slotsPerMomentPool;
  if (p.pass == BAND_PASS_FIELD_TO_OLDER) {
    nextPools[pool].v[momentAt(first, 0, y, z, part)] = X;
    return;
  }
  vec4 omega = PER_CELL_OMEGA ? texelFetch(omegaPerCell, cells) : vec4(p.omega);
  if (PAPER_RULE) {
    // precise: no fused multiply-add, as the CPU reference computes it.
    // Gamma per cell is in the omega buffer: each invocation reads and
    // writes its own cells.
    precise vec4 gamma = clamp(p.gamma0 + (X - rhoBefore) / texelFetch(omegaPerCell, cells),
                               vec4(ADAPTIVE_GAMMA_LOWEST), vec4(ADAPTIVE_GAMMA_HIGHEST));
    storePerCell(cells, gamma);
    precise vec4 tau = 3.0 * gamma + 0.5;
    omega = 1.0 / tau;
  }
  nextPools[pool].v[momentAt(first, 0, y, z, part)] = X + 0.5 * S;
  nextPools[pool].v[momentAt(first, 1, y, z, part)] = (1.0 - omega) * Jx;
  nextPools[pool].v[momentAt(first, 2, y, z, part)] = (1.0 - omega) * Jy;
  nextPools[pool].v[momentAt(first, 3, y, z, part)] = (1.0 - omega) * Jz;
}

void main()
{
  if (!locateRow()) return;
  for (int k = 0; k < 4; ++k) {
    ownA[k] = moment(momentAt(slot, k, y, z, 0));
    ownB[k] = moment(momentAt(slot, k, y, z, 1));
  }
#ifdef BAND_HOLD_ONLY
  // The f a held cell pulls from itself, w_i (rho* + 3 e_i . j*), sum to
  // rho* and their flux is j*: no f is formed.
  collide(ownA[0], ownA[1], ownA[2], ownA[3], ownA[0], 0);
  collide(ownB[0], ownB[1], ownB[2], ownB[3], ownB[0], 1);
#else
  const uint rowBits = texelFetch(streamBits, slot * 64 + z * 8 + y).x;
  const bvec4 streamsA = notEqual(uvec4(rowBits) & uvec4(1, 2, 4, 8), uvec4(0));
  const bvec4 streamsB = notEqual(uvec4(rowBits) & uvec4(16, 32, 64, 128), uvec4(0));
  { OWN_ROW(true, true) PULL(0, 0, 0, 0) PULL(1, 1, 0, 0) PULL(2, -1, 0, 0) }
  { FETCH_ROW(1, 0, true, true) PULL(3, 0, 1, 0) PULL(7, 1, 1, 0) PULL(10, -1, 1, 0) }
  { FETCH_ROW(-1, 0, true, true) PULL(4, 0, -1, 0) PULL(8, -1, -1, 0) PULL(9, 1, -1, 0) }
  { FETCH_ROW(0, 1, true, true) PULL(5, 0, 0, 1) PULL(11, 1, 0, 1) PULL(14, -1, 0, 1) }
  { FETCH_ROW(0, -1, true, true) PULL(6, 0, 0, -1) PULL(12, -1, 0, -1) PULL(13, 1, 0, -1) }
  { FETCH_ROW(1, 1, false, false) PULL(15, 0, 1, 1) }
  { FETCH_ROW(-1, -1, false, false) PULL(16, 0, -1, -1) }
  { FETCH_ROW(1, -1, false, false) PULL(17, 0, 1, -1) }
  { FETCH_ROW(-1, 1, false, false) PULL(18, 0, -1, 1) }
  finish(fa, ownA, streamsA, 0);
  finish(fb, ownB, streamsB, 1);
#endif
}
