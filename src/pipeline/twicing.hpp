// Twicing (Tukey, 1977): smooth, then smooth what the smoothing took away
// and give that back, 2 S X - S^2 X for a smoother S. With S = n lattice
// steps (heat kernel exp(-y) for a ripple, y = k^2 * 2 gamma n) its
// response is 1 - (1 - exp(-y))^2: ripples fade almost as under S while
// the shape, whose curvature S would move by y, moves by only y^2 (mean
// curvature flow's shrinking of thin parts is cancelled to first order).
// The lattice runs S and then S again on its result, so the price is n
// more steps and the field of step n held meanwhile.
// Always with --twicing; by default where it pays (below);
// docs/denoising.md ("Twicing") has the measurements, against OpenVDB.
#pragma once

#include <cstddef>
#include <vector>

namespace lbmshape {

// `once` holds S X, `twice` S^2 X, cell for cell: `once` becomes
// S X + w (S X - S^2 X), what the second smoothing took away given back
// with the weight w: 2 S X - S^2 X with Tukey's w = 1.
inline void twice(std::vector<float>& once, const std::vector<float>& twice, float weight = 1.0f)
{
  for (size_t i = 0; i < once.size(); ++i) once[i] += weight * (once[i] - twice[i]);
}

// --steps auto with twicing: S's steps, twice the k steps plain smoothing
// keeps (the step before its surface speed levelled off at n = k + 1,
// smoothing_stop.hpp). The twiced response over 2k steps is below plain
// smoothing's over k for every ripple that k plain steps halve or more
// (1 - (1 - e^(-2y))^2 < e^(-y) exactly when e^(-y) < 1/2), and keeps the
// shape's slower curvature better.
inline int twicedSteps(int levelledOffAt) { return 2 * (levelledOffAt - 1); }

// Unless told (--twicing, --no-twicing), the default smoothing with steps
// chosen by the noise is twiced when the noise needs at least this many
// plain steps: a smoothing that long erodes thin parts by more than its
// noise leaves (gamma kappa a step), which twicing gives back; a shorter
// one erodes little and twicing would double its steps for nothing.
// Measured on the 33 noisy cases of docs/denoising.md ("Twicing where it
// pays"): every case kept at 3 steps but one that every rule loses is
// ahead of OpenVDB plain, and by more than twiced; every case of 4 or
// more twiced, and three of them (the Fertility at 0.5 voxel, the Kitten
// at 0.25, the Rocker arm at 0.5) only twiced.
inline constexpr int twicingFromSteps = 4;

// Twiced where it pays, three quarters of what the second smoothing took
// are given back, S X + 0.75 (S X - S^2 X): a quarter of plain smoothing's
// first-order thinning stays, and the ripples between the noise and the
// shape come back less (the response 1.75 e^-y - 0.75 e^-2y against
// 2 e^-y - e^-2y). Measured on the same 33 cases with S of 2k steps:
// weights 0.5, 0.75 and 1 ahead of OpenVDB in 28, 32 and 30 of them
// (docs/denoising.md). --twicing keeps Tukey's 1, which keeps thin parts
// best.
inline constexpr float automaticTwicingWeight = 0.75f;

}  // namespace lbmshape
