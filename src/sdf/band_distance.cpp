#include "sdf/band_distance.hpp"

#include <algorithm>

#include "sdf/grid_blocks.hpp"

namespace lbmshape {

size_t exactBandDistances(const TriangleBvh& bvh, const GridFrame& frame, double bandVoxels, Volume& distance,
                          std::vector<uint32_t>& nearest, Progress* progress, double progressWeight)
{
  const Extent3 extent = frame.extent;
  const GridBlocks blocks(extent, 8);
  if (progress) progress->beginPart("exact band", double(blocks.count()), progressWeight);
  const double band = bandVoxels * frame.voxel;
  size_t written = 0;
#pragma omp parallel for schedule(dynamic, 4) reduction(+ : written)
  for (size_t b = 0; b < blocks.count(); ++b) {
    const CellRange r = blocks.range(b);
    if (progress) progress->advance();
    // Every cell of the block is within halfDiagonal of its centre, so when
    // no triangle is within band + halfDiagonal of the centre, no cell of the
    // block is within band of the surface. Most blocks end here.
    const glm::dvec3 first(r.x0, r.y0, r.z0), last(r.x1 - 1, r.y1 - 1, r.z1 - 1);
    const glm::dvec3 centre = frame.toWorld(0.5 * (first + last));
    const double halfDiagonal = 0.5 * frame.voxel * glm::length(last - first);
    uint32_t hint = bvh.closest(centre, band + halfDiagonal).triangle;
    if (hint == TriangleBvh::kNoTriangle) continue;
    for (int z = r.z0; z < r.z1; ++z)
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
          // The previous cell's triangle is usually this cell's too, or
          // nearly as close: its distance is a tight bound that lets the
          // search prune almost everything else.
          const glm::dvec3 p = frame.cellCentre(x, y, z);
          const double bound = std::min(band, bvh.closestOnTriangle(p, hint).distance);
          const TriangleBvh::Closest c = bvh.closest(p, bound);
          if (c.triangle == TriangleBvh::kNoTriangle || c.distance > band) continue;
          const size_t i = extent.index(x, y, z);
          distance[i] = float(c.distance / frame.voxel);
          nearest[i] = c.triangle;
          hint = c.triangle;
          ++written;
        }
  }
  return written;
}

size_t exactFaceDistances(const TriangleBvh& bvh, const GridFrame& frame, Volume& distance,
                          std::vector<uint32_t>& nearest)
{
  const Extent3 e = frame.extent;
  size_t written = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : written)
  for (int row = 0; row < e.ny * e.nz; ++row) {
    const int y = row % e.ny, z = row / e.ny;
    const bool wholeRow = y == 0 || z == 0 || y == e.ny - 1 || z == e.nz - 1;
    uint32_t hint = TriangleBvh::kNoTriangle;
    for (int x = 0; x < e.nx; x += wholeRow || x == e.nx - 1 ? 1 : e.nx - 1) {
      const size_t i = e.index(x, y, z);
      if (nearest[i] != TriangleBvh::kNoTriangle) continue;
      const glm::dvec3 p = frame.cellCentre(x, y, z);
      const TriangleBvh::Closest c = hint == TriangleBvh::kNoTriangle
                                         ? bvh.closest(p)
                                         : bvh.closest(p, bvh.closestOnTriangle(p, hint).distance);
      distance[i] = float(c.distance / frame.voxel);
      nearest[i] = hint = c.triangle;
      ++written;
    }
  }
  return written;
}

}  // namespace lbmshape
