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
// beside it.
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

// The variants are push constants, not specialization constants: one
// pipeline serves every kind of step and the field pass (lavapipe spends
// about 100 ms compiling each pipeline), at the cost of uniform branches.
#define PER_CELL_OMEGA (p.perCellOmega != 0)
#define HAS_SOURCE (p.hasSource != 0)
#define PAPER_RULE (p.paperRule != 0)

layout(set = 0, binding = BAND_BINDING_STREAMS) uniform usamplerBuffer streamBits;
layout(set = 0, binding = BAND_BINDING_OMEGA) uniform samplerBuffer omegaPerCell;
layout(set = 0, binding = BAND_BINDING_SOURCE) uniform samplerBuffer sourceBase;
layout(set = 0, binding = BAND_BINDING_NEXT, std430) writeonly buffer NextPool { vec4 v[]; } nextPools[BAND_MAX_POOLS];
layout(set = 0, binding = BAND_BINDING_FIELD, std430) writeonly buffer FieldPool { vec4 v[]; } fieldPools[BAND_MAX_POOLS];
// Used only with PAPER_RULE: each invocation reads and writes its own cells.
layout(set = 0, binding = BAND_BINDING_GAMMA, rgba32f) uniform imageBuffer gammaPerCell;

vec4 fa[19], fb[19];  // the row's cells 0-3 and 4-7, pulled
vec4 ownA[4], ownB[4];  // the same cells' own moments

#define WEIGHT(EX, EY, EZ) \
  ((EX) * (EX) + (EY) * (EY) + (EZ) * (EZ) == 0 ? W_REST : (EX) * (EX) + (EY) * (EY) + (EZ) * (EZ) == 1 ? W_AXIAL : W_DIAGONAL)
// e . j for a velocity of literal components, without multiplications by 0
// (so the sum is the CPU reference's, term for term).
#define E_DOT(EX, EY, EZ, JX, JY, JZ)                                                      \
  (((EX) == 0 ? vec4(0.0) : float(EX) * (JX)) + ((EY) == 0 ? vec4(0.0) : float(EY) * (JY)) + \
   ((EZ) == 0 ? vec4(0.0) : float(EZ) * (JZ)))

// fa[I], fb[I]: the row's eight cells pull from the cells at -e_I: the row
// (y - EY, z - EZ), possibly in a neighbouring brick, shifted by one cell
// along x for EX != 0 (the cell beyond the row's end from the neighbouring
// brick). A cell whose upstream cell is outside the grid (or, never for a
// streaming cell, outside the band) bounces back: f*_opposite of itself. A
// held cell pulls from itself.
#define PULL(I, EX, EY, EZ)                                                                                    \
  {                                                                                                            \
    const RowPlace row = rowPlace(y - (EY), z - (EZ));                                                         \
    const bool rowValid = row.valid;                                                                           \
    const int rs = row.slot, ly = row.ly, lz = row.lz, by = row.by, bz = row.bz;                               \
    vec4 a[4], b[4];                                                                                           \
    for (int k = 0; k < 4; ++k) {                                                                              \
      a[k] = moment(momentAt(rs, k, ly, lz, 0));                                                               \
      b[k] = moment(momentAt(rs, k, ly, lz, 1));                                                               \
    }                                                                                                          \
    bvec4 validA = bvec4(rowValid), validB = bvec4(rowValid);                                                  \
    if ((EX) == 1) {                                                                                           \
      const int side = neighbourSlot(-1, by, bz);                                                              \
      const bool sideValid = rowValid && origin.x > 0 && side >= 0;                                            \
      for (int k = 0; k < 4; ++k) {                                                                            \
        const float left = moment(momentAt(sideValid ? side : rs, k, ly, lz, 1)).w;                            \
        b[k] = vec4(a[k].w, b[k].xyz);                                                                         \
        a[k] = vec4(left, a[k].xyz);                                                                           \
      }                                                                                                        \
      validA.x = sideValid;                                                                                    \
    } else if ((EX) == -1) {                                                                                   \
      const int side = neighbourSlot(1, by, bz);                                                               \
      const bool sideValid = rowValid && side >= 0;                                                            \
      for (int k = 0; k < 4; ++k) {                                                                            \
        const float right = moment(momentAt(sideValid ? side : rs, k, ly, lz, 0)).x;                           \
        a[k] = vec4(a[k].yzw, b[k].x);                                                                         \
        b[k] = vec4(b[k].yzw, right);                                                                          \
      }                                                                                                        \
      validA = both(validA, lessThan(origin.x + ivec4(1, 2, 3, 4), ivec4(p.nx)));                              \
      validB = both(validB, lessThan(origin.x + ivec4(5, 6, 7, 8), ivec4(p.nx)));                              \
      validB.w = validB.w && sideValid;                                                                        \
    }                                                                                                          \
    const float w = WEIGHT(EX, EY, EZ);                                                                        \
    const vec4 ownDotA = E_DOT(EX, EY, EZ, ownA[1], ownA[2], ownA[3]);                                         \
    const vec4 ownDotB = E_DOT(EX, EY, EZ, ownB[1], ownB[2], ownB[3]);                                         \
    /* held cells pull from themselves (+e), streaming cells at a wall bounce back (-e) */                    \
    fa[I] = mix(w * (ownA[0] + 3.0 * mix(ownDotA, -ownDotA, streamsA)),                                        \
                w * (a[0] + 3.0 * E_DOT(EX, EY, EZ, a[1], a[2], a[3])), both(validA, streamsA));               \
    fb[I] = mix(w * (ownB[0] + 3.0 * mix(ownDotB, -ownDotB, streamsB)),                                        \
                w * (b[0] + 3.0 * E_DOT(EX, EY, EZ, b[1], b[2], b[3])), both(validB, streamsB));               \
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
// source, then the collision or the field, for one half of the row.
void collide(vec4 sum, vec4 Jx, vec4 Jy, vec4 Jz, vec4 rhoBefore, int part);

void finish(vec4 f[19], vec4 rhoBefore, int part)
{
  const vec4 sum = f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8] + f[9] + f[10] + f[11] + f[12] +
                   f[13] + f[14] + f[15] + f[16] + f[17] + f[18];
  const vec4 Jx = f[1] - f[2] + f[7] - f[8] + f[9] - f[10] + f[11] - f[12] + f[13] - f[14];
  const vec4 Jy = f[3] - f[4] + f[7] - f[8] - f[9] + f[10] + f[15] - f[16] + f[17] - f[18];
  const vec4 Jz = f[5] - f[6] + f[11] - f[12] - f[13] + f[14] + f[15] - f[16] - f[17] + f[18];
  collide(sum, Jx, Jy, Jz, rhoBefore, part);
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
    const int pool = slot / p.slotsPerFieldPool, first = slot - pool * p.slotsPerFieldPool;
    fieldPools[pool].v[(first * 64 + z * 8 + y) * 2 + part] = field;
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
    precise vec4 gamma = clamp(p.gamma0 + (X - rhoBefore) / imageLoad(gammaPerCell, cells),
                               vec4(ADAPTIVE_GAMMA_LOWEST), vec4(ADAPTIVE_GAMMA_HIGHEST));
    imageStore(gammaPerCell, cells, gamma);
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
  const vec4 streamsA = vec4(notEqual(uvec4(rowBits) & uvec4(1, 2, 4, 8), uvec4(0)));
  const vec4 streamsB = vec4(notEqual(uvec4(rowBits) & uvec4(16, 32, 64, 128), uvec4(0)));
  const bvec4 streamsAb = notEqual(streamsA, vec4(0.0)), streamsBb = notEqual(streamsB, vec4(0.0));
#define streamsA streamsAb
#define streamsB streamsBb
  PULL(0, 0, 0, 0)
  PULL(1, 1, 0, 0) PULL(2, -1, 0, 0) PULL(3, 0, 1, 0) PULL(4, 0, -1, 0) PULL(5, 0, 0, 1) PULL(6, 0, 0, -1)
  PULL(7, 1, 1, 0) PULL(8, -1, -1, 0) PULL(9, 1, -1, 0) PULL(10, -1, 1, 0)
  PULL(11, 1, 0, 1) PULL(12, -1, 0, -1) PULL(13, 1, 0, -1) PULL(14, -1, 0, 1)
  PULL(15, 0, 1, 1) PULL(16, 0, -1, -1) PULL(17, 0, 1, -1) PULL(18, 0, -1, 1)
  finish(fa, ownA[0], 0);
  finish(fb, ownB[0], 1);
#endif
}
