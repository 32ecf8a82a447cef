// How far from the surface the narrow-band lattice must stream, for a run
// of `steps` steps at diffusion coefficient gamma (voxels^2 per step).
//
// A lattice step moves information one cell, so after n steps a cell
// depends only on cells within n cells of it: with every cell within n + 2
// of the surface streaming (the surface itself moves less than a voxel and
// marching cubes reads a cell further), the result is the grid's, exactly.
// Most runs need less. A held cell at the band's edge keeps its starting
// value where the grid's would have changed by delta = gamma n Laplacian(X)
// (for a distance field, the curvature of its level set there: 2/(R + W)
// outside a sphere of radius R; at most about a voxel where a kink of the
// medial axis is smoothed), and that difference reaches the surface by
// diffusion, attenuated over a distance L by erfc(L / sqrt(4 gamma n)). With
// L = W - 1 (the surface moves less than a voxel) at least two such lengths,
// erfc(2) = 4.7e-3 of delta: a few thousandths of a voxel at most. So
//     W = min(n + 2, 1 + ceil(2 sqrt(4 gamma n))), at least 3:
// 6 voxels for 7 steps of 0.2 (instead of 9), 7 for denoise's default,
// whose edge-finding copy takes 5 steps of 0.57 (pipeline/feature_probe.hpp),
// 8 for a 48-frame morph at 0.05 (instead of 49). Measured
// (docs/lattice-theory.md): the armadillo denoised at 128 and 256 cells
// with W from 4 to 9 lies equally close to the dense grid's result (0.0026
// voxel mean at 128, the same Hausdorff distance).
#pragma once

#include <algorithm>
#include <cmath>

namespace lbmshape {

inline double streamingHalfWidth(double gamma, double steps)
{
  const double diffusionLengths = 2.0;  // erfc(2) = 4.7e-3
  const double diffusive = 1.0 + std::ceil(diffusionLengths * std::sqrt(4.0 * gamma * std::max(steps, 0.0)));
  return std::max(3.0, std::min(steps + 2.0, diffusive));
}

}  // namespace lbmshape
