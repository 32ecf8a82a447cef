#include "sdf/band_distance.hpp"

#include <algorithm>

#include "sdf/cell_space.hpp"

namespace lbmshape {

namespace {

template <class Cells>
size_t exactBandDistancesIn(const Cells& cells, const TriangleBvh& bvh, const GridFrame& frame, double bandVoxels,
                            float* distance, uint32_t* nearest, Progress* progress, double progressWeight)
{
  if (progress) progress->beginPart("exact band", double(cells.blockCount()), progressWeight);
  const double band = bandVoxels * frame.voxel;
  size_t written = 0;
#pragma omp parallel for schedule(dynamic, 4) reduction(+ : written)
  for (size_t b = 0; b < cells.blockCount(); ++b) {
    glm::ivec3 lo, hi;
    cells.blockRange(b, lo, hi);
    if (progress) progress->advance();
    // Every cell of the block is within halfDiagonal of its centre, so when
    // no triangle is within band + halfDiagonal of the centre, no cell of the
    // block is within band of the surface. Most blocks end here.
    const glm::dvec3 first(lo), last(hi - 1);
    const glm::dvec3 centre = frame.toWorld(0.5 * (first + last));
    const double halfDiagonal = 0.5 * frame.voxel * glm::length(last - first);
    uint32_t hint = bvh.closest(centre, band + halfDiagonal).triangle;
    if (hint == TriangleBvh::kNoTriangle) continue;
    cells.forEachCellOf(b, [&](size_t i, const glm::ivec3& c) {
      // The previous cell's triangle is usually this cell's too, or
      // nearly as close: its distance is a tight bound that lets the
      // search prune almost everything else.
      const glm::dvec3 p = frame.toWorld(glm::dvec3(c));
      const double bound = std::min(band, bvh.closestOnTriangle(p, hint).distance);
      const TriangleBvh::Closest found = bvh.closest(p, bound);
      if (found.triangle == TriangleBvh::kNoTriangle || found.distance > band) return;
      distance[i] = float(found.distance / frame.voxel);
      nearest[i] = found.triangle;
      hint = found.triangle;
      ++written;
    });
  }
  return written;
}

}  // namespace

size_t exactBandDistances(const TriangleBvh& bvh, const GridFrame& frame, double bandVoxels, Volume& distance,
                          std::vector<uint32_t>& nearest, Progress* progress, double progressWeight)
{
  return exactBandDistancesIn(GridCells(frame.extent, 8), bvh, frame, bandVoxels, distance.data(), nearest.data(),
                              progress, progressWeight);
}

size_t exactBandDistances(const TriangleBvh& bvh, const GridFrame& frame, const BandCells& cells, double bandVoxels,
                          std::vector<float>& distance, std::vector<uint32_t>& nearest, Progress* progress,
                          double progressWeight)
{
  return exactBandDistancesIn(cells, bvh, frame, bandVoxels, distance.data(), nearest.data(), progress, progressWeight);
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
