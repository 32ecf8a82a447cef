// --preserve-features finds the edges on a copy of the field first smoothed
// isotropically to a variance of 4 voxels^2 (a diffusion length of 2
// voxels: the noise is gone, sharp edges are still sharp bends). How the
// copy is smoothed is the probe's own business, not the user's --gamma: it
// takes the fewest lattice steps that reach that variance.
#pragma once

namespace lbmshape {

struct FeatureProbe {
  int steps = 0;
  double gamma = 0.0;  // voxels^2 per step
};

// The variance the copy is smoothed to, in voxels^2.
inline constexpr double featureProbeVariance = 4.0;

// A run of n steps from equilibrium spreads a pulse by 2 gamma n (1 +
// relaxation::startUpError), less than 2 gamma n at first: the steps and
// gamma are chosen together. The fewest steps for which some gamma up to
// parameter_bounds::maxGamma reaches featureProbeVariance, and the gamma
// that reaches it exactly in that many: 5 steps of gamma = 0.57 (the probe
// took 10 steps of 0.2 before, 3.93 voxels^2).
FeatureProbe featureProbe();

// The variance a run of `steps` steps at `gamma` spreads a pulse to.
double spreadVariance(double gamma, int steps);

}  // namespace lbmshape
