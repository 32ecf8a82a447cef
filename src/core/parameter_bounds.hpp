// The ranges of the commands' numeric parameters, beyond which a job is
// refused (UsageError, exit 2) before any work: one place for the checks,
// the --help texts and docs/batch.md to agree on.
#pragma once

#include <cstddef>

namespace lbmshape::parameter_bounds {

// Lattice steps of one denoise or one whole morph: a million steps of a
// 128^3 band take hours; more is a typo.
inline constexpr long maxSteps = 1'000'000;
// Timed runs of one bench: the median of more tells nothing new.
inline constexpr int maxBenchRuns = 1000;
// Frames of one morph: each is a mesh file.
inline constexpr int maxFrames = 100'000;
// gamma, voxels^2 per step. Above 1, tau = 3 gamma + 1/2 > 3.5 and the
// lattice relaxes by less than 1/tau = 0.29 a step: over the few steps of a
// denoise it moves X ballistically, not by the diffusion equation
// (docs/lattice-theory.md). More smoothing is more steps.
inline constexpr double maxGamma = 1.0;
// The morph's Cs, per step. The lattice treats the source term by the
// trapezoidal rule, so a step shrinks X - X_target by (1 - Cs/2)/(1 + Cs/2):
// a third at 1 (what a morph's closing ends with), nothing left at 2, a
// change of sign beyond. Past 1 a morph is over in a few steps, too few for
// the diffusion that keeps the shapes in between smooth.
inline constexpr double maxCs = 1.0;
// Below this a morph that arrives (its steps chosen by the distance to go)
// needs more than maxSteps: each step closes about Cs of the distance left,
// and arriving from 100 voxels away within 0.01 takes ln(1e4)/Cs = 92,000
// steps at 1e-4. (--cs 1e-9 ran into maxSteps, hours, without a word.)
inline constexpr double minCs = 1e-4;
// The paper's noise (--noise), a fraction of the field's largest |X|: the
// paper adds 5 %; at 100 % the noise is as large as the whole field and no
// surface is left to smooth.
inline constexpr double maxNoise = 1.0;
// The morph's --tolerance, voxels: the largest |X - X_target| near the
// target's surface at which a frame counts as arrived. A frame a voxel or
// more off is not at the target (#12 asks for a last frame within a voxel
// of it everywhere), and `inf` made every morph "arrive" before its first
// step.
inline constexpr double maxTolerance = 1.0;
// Surface samples of compare, per mesh: about 100 bytes each.
inline constexpr std::size_t maxSamples = 10'000'000;

// Pictures (render, --preview): a side of at most 8192 pixels and at most
// 16.8 M pixels in all, about 700 MB of device memory with 4 samples per
// pixel and their depth; larger is a typo for a picture a person looks at.
inline constexpr int minPictureSide = 16;
inline constexpr int maxPictureSide = 8192;
inline constexpr long maxPicturePixels = 4096L * 4096L;
// Meshes one picture shows (from a folder, --count; in all): cells of a
// contact sheet.
inline constexpr int maxFolderMeshes = 256;

}  // namespace lbmshape::parameter_bounds
