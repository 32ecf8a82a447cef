// The distance-field lattice Boltzmann solver (paper sections 3.1-3.3, 4).
//
// State: 19 distributions per cell on a D3Q19 lattice. One step is a fused
// pull-stream and BGK collision,
//     f_i(r)   = f*_i(r - e_i)                 (streaming; bounce-back at walls)
//     X        = sum_i f_i + S/2               (the field, second-order with S)
//     f*_i(r)  = f_i + omega (w_i X - f_i) + (1 - omega/2) w_i S
// which solves dX/dt = gamma Laplacian(X) + S with gamma = (1/omega - 1/2)/3.
// The source is linear in X, S = A - c X, so the morph force of section 5.2
// (A = Cs X_target, c = Cs) is handled exactly: X = (sum f + A/2) / (1 + c/2).
// docs/lattice-theory.md derives each of these choices.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "lbmshape/core/extent.hpp"
#include "lbmshape/core/volume.hpp"
#include "lbmshape/lbm/adaptive_gamma.hpp"
#include "lbmshape/lbm/stepping_solver.hpp"

namespace lbmshape {

// S = scale * base - decay * X in every cell. The morph's force is
// Cs (X_target - X): base X_target, scale and decay Cs, so that a change of
// Cs changes two numbers (setSourceStrength), not a field to upload.
struct LinearSource {
  Volume base;
  float decay = 0.0f;
  float scale = 1.0f;
};

class LatticeSolver : public SteppingSolver {
public:
  virtual Extent3 extent() const = 0;

  // Relaxation: one diffusion coefficient everywhere (voxels^2 per step), or
  // one per cell (the anisotropic gamma of section 5.1). Both are checked.
  virtual void setUniformGamma(double gamma) = 0;
  virtual void setGammaPerCell(const Volume& gamma) = 0;
  // The paper's anisotropic rule (section 5.1, Eq. 20), applied by the
  // solver at every step, on the device for a device's solver: each cell
  // collides with gamma = gamma0 + (X - X before) / gamma before, clamped to
  // [adaptive_gamma::lowest, highest], X being what the step pulls and X
  // before and gamma before what the cell's last step pulled and used (at
  // the first step, gamma0). Call before initialize(); a
  // source cannot be set with it. Undone by the two setters above.
  virtual void setPaperRule(double gamma0) = 0;
  // lbmshape's feature-preserving rule (adaptive_gamma::featurePreservingRule)
  // on the field now, as gamma per cell: here on the host, from the field;
  // the Vulkan solver runs it on the device.
  virtual void setFeaturePreservingGamma(double gamma0, double kappaEdge)
  {
    setGammaPerCell(adaptive_gamma::featurePreservingRule(field(), gamma0, kappaEdge));
  }

  // Source term; std::nullopt removes it.
  virtual void setSource(std::optional<LinearSource> source) = 0;
  // The source's decay and scale, its base kept: logic_error without a
  // source. Takes effect at the next step, with no upload.
  virtual void setSourceStrength(float decay, float scale) = 0;

  // Restart from field X, with every distribution at its equilibrium w_i X.
  // Call after setSource: the initial distributions account for S/2.
  virtual void initialize(const Volume& field) = 0;

  // The field X after the steps taken so far.
  virtual Volume field() = 0;
  // The same into `out`, whose memory is used again where it has the
  // grid's extent (a morph's frames: no new pages to fault in and clear).
  virtual void fieldInto(Volume& out) { out = field(); }
  // fieldInto(out), then step(1), under the source strength `next` from
  // that step on where given (setSourceStrength): where the solver can, in
  // one pass over the lattice, the step storing the field it starts from
  // anyway (a morph's frames: no field pass of their own).
  virtual void fieldIntoThenStep(Volume& out, std::optional<SourceStrength> next)
  {
    fieldInto(out);
    if (next) setSourceStrength(next->decay, next->scale);
    step(1);
  }
  // X one step before that: the copy the last step read stays intact until
  // the next step, so this costs what field() does. Throws std::logic_error
  // before two steps.
  virtual Volume previousField() = 0;
};

}  // namespace lbmshape
