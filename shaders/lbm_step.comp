#version 450
#extension GL_GOOGLE_include_directive : require
// One lattice Boltzmann step: pull-streaming, then BGK collision towards
// f_eq = w_i X with the source share (1 - omega/2) w_i S, stored as the
// post-collision distributions for the next step.
//
// With PAPER_RULE the relaxation is the paper's anisotropic rule (section
// 5.1, Eq. 20), run here so that no field leaves the device between steps:
// the cell collides with
//     gamma = clamp(gamma0 + (X - X before) / gamma before)
// where X before and gamma before are what its last step pulled and used
// (at the first step, what it pulls and gamma0: the field buffer holds the
// field pass's X), and keeps both for the next step. src/lbm/reference_solver.cpp does the same on the CPU.
#include "lattice.glsl"
#include "adaptive_gamma_bounds.h"

layout(constant_id = LATTICE_SPEC_PAPER_RULE) const bool PAPER_RULE = false;

// The next lattice copy, one binding per row group.
layout(set = 0, binding = LATTICE_BINDING_NEXT, std430) writeonly buffer Distribution { vec4 cells[]; } nextGroup[GROUPS];
// Used with PAPER_RULE, and written with params.writeField: each invocation
// reads and writes its own block.
layout(set = 0, binding = LATTICE_BINDING_FIELD, std430) buffer FieldBefore { vec4 cells[]; } fieldBefore;
layout(set = 0, binding = LATTICE_BINDING_GAMMA, std430) buffer Gamma { vec4 cells[]; } gammaPerCell;

#define COLLIDE(I, EX, EY, EZ)                                                                   \
  nextGroup[ROW_GROUP(EY, EZ)].cells[INDEX_IN_GROUP(ownBlock, EX, EY, EZ)] =                     \
      f[I] + omega * (WEIGHT(EX, EY, EZ) * X - f[I]) + sourceShare * WEIGHT(EX, EY, EZ) * S;

void main()
{
  if (!locateBlock()) return;
  FOR_EACH_DIRECTION(PULL)
  const vec4 sum = distributionSum();
  vec4 S;
  vec4 X = fieldFromSum(sum, params.decay, params.baseScale, S);
  vec4 omega;
  if (PAPER_RULE) {
    // precise: no fused multiply-add, as the CPU reference computes it; the
    // rule divides by gamma, so a difference in rounding would grow.
    precise vec4 gamma = clamp(params.gamma0 + (X - fieldBefore.cells[ownBlock]) / gammaPerCell.cells[ownBlock],
                               vec4(ADAPTIVE_GAMMA_LOWEST), vec4(ADAPTIVE_GAMMA_HIGHEST));
    gammaPerCell.cells[ownBlock] = gamma;
    fieldBefore.cells[ownBlock] = X;
    precise vec4 tau = 3.0 * gamma + 0.5;
    omega = 1.0 / tau;
  } else {
    omega = PER_CELL_OMEGA ? texelFetch(omegaPerCell, ownBlock) : vec4(params.omega);
    // The field of the state this step starts from, for a frame, as the
    // field pass would store it under the source of the steps before (a
    // morph may raise Cs from this step on); the paper's rule keeps its
    // own X there.
    if (params.writeField != 0) {
      vec4 unused;
      fieldBefore.cells[ownBlock] = fieldFromSum(sum, params.fieldDecay, params.fieldBaseScale, unused);
    }
  }
  vec4 sourceShare = 1.0 - 0.5 * omega;
  FOR_EACH_DIRECTION(COLLIDE)
}
