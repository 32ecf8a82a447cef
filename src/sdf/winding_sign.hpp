// Stage 2 of the signed distance: which cells are inside (generalized
// winding number above 1/2), without evaluating the winding number at every
// cell.
//
// Why it is safe. Off the surface w is harmonic, hence smooth, and
// WindingGradientBound bounds |grad w| over any box from the uncancelled
// (hole) edges alone. If the segment between two neighbouring cells x, y
// misses the surface, |w(y) - w(x)| <= voxel * (that bound over the segment).
// The segment certainly misses the surface when d(x) + d(y) exceeds its
// length, one voxel (a surface point z on it would give d(x) + d(y) <=
// |x - z| + |z - y|); the distance stage knows d exactly wherever that sum
// can be that small.
// So each cell carries an interval [w - r, w + r] known to contain its
// winding number: evaluated cells start with r = the evaluation's accuracy,
// and a flood fill hands the interval on across certified segments, widening
// it by the gradient bound. Wherever the interval would straddle 1/2, the
// cell is evaluated instead. For a closed mesh (no open edges) w is constant
// off the surface and a handful of evaluations decides every cell; near hole
// rims the bound is large and cells are evaluated individually.
#pragma once

#include <cstdint>
#include <vector>

#include "lbmshape/core/volume.hpp"
#include "lbmshape/sdf/grid_frame.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
#include "lbmshape/sdf/winding_gradient_bound.hpp"

namespace lbmshape {

// `distance` is the unsigned distance in voxels, where each value must be at
// most the true distance unless the cell is truly more than a voxel from the
// surface (so band cells exact and infinity beyond the band will do). Returns
// one flag per cell (1 = inside); `evaluations` receives the number of fast
// winding-number queries made.
std::vector<uint8_t> insideByWindingNumber(const TriangleBvh& bvh, const WindingGradientBound& gradient,
                                           const GridFrame& frame, const Volume& distance, size_t& evaluations);

// The same for the cells of the narrow band's bricks: `distance` holds one
// value per stored cell (BandCells numbering); cells beyond the grid are
// skipped (their flag is 0).
class BandCells;
std::vector<uint8_t> insideByWindingNumber(const TriangleBvh& bvh, const WindingGradientBound& gradient,
                                           const GridFrame& frame, const BandCells& cells,
                                           const std::vector<float>& distance, size_t& evaluations);

}  // namespace lbmshape
