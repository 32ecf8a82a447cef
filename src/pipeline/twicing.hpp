// Twicing (Tukey, 1977): smooth, then smooth what the smoothing took away
// and give that back, 2 S X - S^2 X for a smoother S. With S = n lattice
// steps (heat kernel exp(-y) for a ripple, y = k^2 * 2 gamma n) its
// response is 1 - (1 - exp(-y))^2: ripples fade almost as under S while
// the shape, whose curvature S would move by y, moves by only y^2 (mean
// curvature flow's shrinking of thin parts is cancelled to first order).
// The lattice runs S and then S again on its result, so the price is n
// more steps and the field of step n held meanwhile.
// Opt-in (--twicing) for that price; docs/denoising.md ("Twicing") has the
// measurements, against OpenVDB and the default.
#pragma once

#include <cstddef>
#include <vector>

namespace lbmshape {

// `once` holds S X, `twice` S^2 X, cell for cell: `once` becomes 2 S X - S^2 X.
inline void twice(std::vector<float>& once, const std::vector<float>& twice)
{
  for (size_t i = 0; i < once.size(); ++i) once[i] = 2.0f * once[i] - twice[i];
}

// --steps auto with twicing: S's steps, twice the k steps plain smoothing
// keeps (the step before its surface speed levelled off at n = k + 1,
// smoothing_stop.hpp). The twiced response over 2k steps is below plain
// smoothing's over k for every ripple that k plain steps halve or more
// (1 - (1 - e^(-2y))^2 < e^(-y) exactly when e^(-y) < 1/2), and keeps the
// shape's slower curvature better.
inline int twicedSteps(int levelledOffAt) { return 2 * (levelledOffAt - 1); }

}  // namespace lbmshape
