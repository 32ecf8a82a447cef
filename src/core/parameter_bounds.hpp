// The ranges of the commands' numeric parameters, beyond which a job is
// refused (UsageError, exit 2) before any work: one place for the checks,
// the --help texts and docs/batch.md to agree on.
#pragma once

#include <cstddef>

namespace lbmshape::parameter_bounds {

// Lattice steps of one denoise or one whole morph: a million steps of a
// 128^3 band take hours; more is a typo.
inline constexpr long maxSteps = 1'000'000;
// Frames of one morph: each is a mesh file.
inline constexpr int maxFrames = 100'000;
// gamma, voxels^2 per step. Above 1, tau = 3 gamma + 1/2 > 3.5 and the
// lattice relaxes by less than 1/tau = 0.29 a step: over the few steps of a
// denoise it moves X ballistically, not by the diffusion equation
// (docs/lattice-theory.md). More smoothing is more steps.
inline constexpr double maxGamma = 1.0;
// The morph's Cs, per step: the source term moves X by Cs (X_target - X) a
// step, so beyond 1 it overshoots the target.
inline constexpr double maxCs = 1.0;
// Surface samples of compare, per mesh: about 100 bytes each.
inline constexpr std::size_t maxSamples = 10'000'000;

}  // namespace lbmshape::parameter_bounds
