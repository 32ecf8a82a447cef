// How a morph spends its lattice steps: how many, where its frames fall, and
// the diffusion coefficient of each step.
//
// The paper's scheme (constant gamma and Cs) does not end at the target: its
// steady state solves gamma Laplacian(X) = Cs (X - X_target), so the surface
// stays about gamma/Cs times the target's mean curvature away from it, and
// thin parts (fingers, ears, a thin ring) are eroded. A morph that arrives
// keeps gamma and Cs for its first half, where the surface travels and the
// diffusion keeps the shapes in between smooth, then closes: gamma falls to
// arrivalGamma and Cs rises to arrivalCs, so the offset shrinks by
// (gamma/Cs) / (arrivalGamma/arrivalCs) = 500 at the defaults. Lowering
// gamma alone does not do it: near tau = 1/2 the lattice's flux relaxes by
// |1 - 1/tau| ~ 1 a step, so the flux of the first half lingers where the
// target's distance field has a kink (docs/morphing.md measures both).
// It runs until the source term has closed the distance: without diffusion
// X - X_target shrinks by rho = (1 - Cs/2)/(1 + Cs/2) a step (the
// second-order source, docs/lattice-theory.md), and diffusion and the
// closing's larger Cs only shorten that, so
//     steps = ceil(ln(E0 / tolerance) / ln(1/rho))
// from the largest distance E0 between the two fields near the target. The
// frames are spread evenly in time over those steps, so --frames says how
// many pictures, never where the morph ends. So that every frame lies the
// same number of steps from the one before (at least one), gamma and Cs of
// every step are scaled by one factor, the number of steps becoming the
// nearest multiple of the frames' intervals: the same
// dX/dt = gamma Laplacian(X) + Cs (X_target - X), solved in steps that
// much shorter or longer. Frames repeated the one before where the morph
// had fewer steps than frames, and where the steps did not divide evenly
// some frames moved twice as far as their neighbours: the clip played in
// jerks.
//
// Given steps (--steps or --steps-per-frame) keep the paper's scheme:
// constant gamma, ending where the steps end.
#pragma once

#include <vector>

namespace lbmshape {

struct MorphOptions;

// gamma and Cs a morph that arrives ends with: the offset from the target is
// then 1/1000 of its curvature (voxels). Cs stays within the users' range
// (core/parameter_bounds.hpp).
inline constexpr double arrivalGamma = 0.001;
inline constexpr double arrivalCs = 1.0;

class MorphSchedule {
public:
  // The paper's: constant gamma over the steps the options give (one a
  // frame by default).
  static MorphSchedule fixed(const MorphOptions& options);
  // The morph that arrives: steps from `initialError`, the largest
  // |X_source - X_target| (voxels) near the target's surface.
  static MorphSchedule arriving(const MorphOptions& options, double initialError);
  // Steps for the source term alone to shrink `initialError` below
  // `tolerance` at speed Cs; 0 where it is not above it.
  static int stepsToArrive(double initialError, double cs, double tolerance);

  bool annealed() const { return annealFrom_ < totalSteps_ && (gammaEnd_ != gamma_ || csEnd_ != cs_); }
  // The first step of the closing (totalSteps() when there is none).
  int annealFrom() const { return annealFrom_; }
  int totalSteps() const { return totalSteps_; }
  // gamma and Cs of every step as a fraction of the options': below 1
  // where the morph takes more steps than it would have (more frames than
  // its steps), above 1 (at most 3/2) where fewer, so that every frame
  // is the same number of steps from the one before.
  double scale() const { return scale_; }
  // Frame k shows the field after frameSteps()[k] steps; the last is totalSteps().
  const std::vector<int>& frameSteps() const { return frameSteps_; }
  // gamma and Cs of the step that starts after `step` steps.
  double gammaAt(int step) const;
  double csAt(int step) const;
  // The first step after `step` whose gamma or Cs may differ from step's
  // (totalSteps() if none): steps up to it can run as one batch.
  int sameStepsUntil(int step) const;
  // The sum of gamma over all steps: the run's total diffusion, voxels^2
  // (what sets the narrow band's width).
  double totalDiffusion() const;

private:
  // The factor on gamma and Cs that makes the morph take the same whole
  // number of steps between every two frames (at least one), the number
  // nearest its own steps per frame; 1 where they already are.
  static double evenStepsScale(double initialError, const MorphOptions& options, int steps);
  MorphSchedule(double gamma, double cs, double gammaEnd, double csEnd, int totalSteps, int annealFrom, int frames,
                double scale = 1.0);
  double closingLeft(int step) const;

  double gamma_, cs_;
  double gammaEnd_, csEnd_;  // at the last step
  int totalSteps_;
  int annealFrom_;  // the closing's first step
  double scale_;
  std::vector<int> frameSteps_;
};

}  // namespace lbmshape
