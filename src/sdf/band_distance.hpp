// Stage 1 of the signed distance: exact unsigned distances near the surface.
#pragma once

#include <cstdint>
#include <vector>

#include "lbmshape/core/volume.hpp"
#include "lbmshape/sdf/grid_frame.hpp"
#include "lbmshape/core/progress.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

namespace lbmshape {

// For every cell whose centre is within bandVoxels of the surface, writes
// its exact distance (in voxels) to `distance` and its nearest triangle to
// `nearest`; other cells are left untouched. Returns how many cells it wrote.
// Cells it leaves are certainly farther than bandVoxels. Reports its blocks
// to `progress` (if any) as a part of weight `progressWeight`.
size_t exactBandDistances(const TriangleBvh& bvh, const GridFrame& frame, double bandVoxels, Volume& distance,
                          std::vector<uint32_t>& nearest, Progress* progress = nullptr, double progressWeight = 1.0);

// The same for the cells of the narrow band's bricks (BandCells numbering).
class BandCells;
size_t exactBandDistances(const TriangleBvh& bvh, const GridFrame& frame, const BandCells& cells, double bandVoxels,
                          std::vector<float>& distance, std::vector<uint32_t>& nearest, Progress* progress = nullptr,
                          double progressWeight = 1.0);

// Exact distances (and nearest triangles) for the cells on the grid's six
// faces that have none yet. The far field only spreads triangles that some
// cell already holds, so when part of the mesh lies outside the grid, the
// faces must bring in the triangles there. Returns how many cells it wrote.
size_t exactFaceDistances(const TriangleBvh& bvh, const GridFrame& frame, Volume& distance,
                          std::vector<uint32_t>& nearest);

}  // namespace lbmshape
