// How far from the surface the narrow-band lattice must stream, for a run
// of `steps` steps at diffusion coefficient gamma (voxels^2 per step).
//
// A lattice step moves information one cell, so after n steps a cell
// depends only on cells within n cells of it: with every cell within n + 2
// of the surface streaming (the surface itself moves less than a voxel and
// marching cubes reads a cell further), the result is the grid's, exactly.
// Long runs need less: a held cell at the band's edge keeps its starting
// value where the grid's would have changed by gamma n Laplacian(X) (about
// gamma n / R for a surface of radius R), and that difference spreads
// inward by diffusion, which over a length L attenuates it by erfc(L /
// sqrt(4 gamma n)). At four diffusion lengths sqrt(2 gamma n) from the
// surface that is erfc(2.8) = 7e-5 of an already small difference. So
//     W = min(n + 2, 2 + ceil(4 sqrt(2 gamma n))), at least 3:
// 9 voxels for denoise's defaults (7 steps of 0.2, exact), 12 for a
// 48-frame morph at 0.05 (instead of 49).
#pragma once

#include <algorithm>
#include <cmath>

namespace lbmshape {

inline double streamingHalfWidth(double gamma, double steps)
{
  const double diffusive = 2.0 + std::ceil(4.0 * std::sqrt(2.0 * gamma * std::max(steps, 0.0)));
  return std::max(3.0, std::min(steps + 2.0, diffusive));
}

}  // namespace lbmshape
