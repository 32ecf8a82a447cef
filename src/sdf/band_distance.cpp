#include "sdf/band_distance.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>

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

namespace {

// Triangle by triangle: each visits the band's cells within the band around
// it and keeps, per cell, the nearest so far.
size_t exactBandByTriangles(const TriangleBvh& bvh, const GridFrame& frame, const BandCells& cells, double bandVoxels,
                            std::vector<float>& distance, std::vector<uint32_t>& nearest, Progress* progress,
                            double progressWeight)
{
  const BrickSet& bricks = cells.bricks();
  const Extent3& e = bricks.cells();
  const size_t count = bvh.triangleCount();
  if (progress) progress->beginPart("exact band", double(count), progressWeight);
  // The nearest triangle of each cell so far: its squared distance's float
  // bits (which order as the distances do) and the triangle, packed so that
  // one atomic minimum keeps the nearest, ties going to the lower triangle.
  std::vector<uint64_t> best(cells.count(), ~uint64_t(0));
  const double band = bandVoxels * frame.voxel;
  const double halfDiagonal = 0.5 * (brickEdge - 1) * std::sqrt(3.0) * frame.voxel;
#pragma omp parallel for schedule(dynamic, 256)
  for (size_t t = 0; t < count; ++t) {
    if (progress && t % 256 == 0) progress->advance(256);
    const uint32_t triangle = uint32_t(t);
    glm::dvec3 lo, hi;
    bvh.triangleBounds(triangle, lo, hi);
    const glm::ivec3 first = glm::max(glm::ivec3(glm::ceil(frame.toGrid(lo) - bandVoxels)), glm::ivec3(0));
    const glm::ivec3 last =
        glm::min(glm::ivec3(glm::floor(frame.toGrid(hi) + bandVoxels)), glm::ivec3(e.nx - 1, e.ny - 1, e.nz - 1));
    if (glm::any(glm::lessThan(last, first))) continue;
    const glm::ivec3 firstBrick = first / brickEdge, lastBrick = last / brickEdge;
    for (int bz = firstBrick.z; bz <= lastBrick.z; ++bz)
      for (int by = firstBrick.y; by <= lastBrick.y; ++by)
        for (int bx = firstBrick.x; bx <= lastBrick.x; ++bx) {
          const int32_t slot = bricks.slot(bx, by, bz);
          if (slot == noBrick) continue;
          const glm::ivec3 origin = brickEdge * glm::ivec3(bx, by, bz);
          const glm::dvec3 centre = frame.toWorld(glm::dvec3(origin) + 0.5 * (brickEdge - 1));
          if (bvh.closestOnTriangle(centre, triangle).distance > band + halfDiagonal) continue;
          const glm::ivec3 from = glm::max(first, origin), to = glm::min(last, origin + brickEdge - 1);
          for (int z = from.z; z <= to.z; ++z)
            for (int y = from.y; y <= to.y; ++y)
              for (int x = from.x; x <= to.x; ++x) {
                const double d = bvh.closestOnTriangle(frame.cellCentre(x, y, z), triangle).distance;
                if (d > band) continue;
                const size_t i = size_t(slot) * brickCells + size_t(cellInBrick(x & 7, y & 7, z & 7));
                const float v = float(d / frame.voxel);
                const uint64_t packed = uint64_t(std::bit_cast<uint32_t>(v)) << 32 | triangle;
                std::atomic_ref<uint64_t> slotBest(best[i]);
                uint64_t old = slotBest.load(std::memory_order_relaxed);
                while (packed < old && !slotBest.compare_exchange_weak(old, packed, std::memory_order_relaxed)) {
                }
              }
        }
  }
  size_t written = 0;
#pragma omp parallel for schedule(static) reduction(+ : written)
  for (size_t i = 0; i < best.size(); ++i) {
    if (best[i] == ~uint64_t(0)) continue;
    distance[i] = std::bit_cast<float>(uint32_t(best[i] >> 32));
    nearest[i] = uint32_t(best[i]);
    ++written;
  }
  return written;
}

// Cells a triangle's neighbourhood spans, summed over the triangles: the
// work of exactBandByTriangles.
double triangleNeighbourhoods(const TriangleBvh& bvh, const GridFrame& frame, double bandVoxels)
{
  double cells = 0.0;
  for (uint32_t t = 0; t < bvh.triangleCount(); ++t) {
    glm::dvec3 lo, hi;
    bvh.triangleBounds(t, lo, hi);
    const glm::dvec3 span = (hi - lo) / frame.voxel + 2.0 * bandVoxels;
    cells += span.x * span.y * span.z;
  }
  return cells;
}

}  // namespace

// On the band, the cheaper of two ways. Asking the hierarchy cell by cell
// asks about every cell of every band brick, most of them farther than the
// band; going triangle by triangle visits each triangle's neighbourhood,
// which on a fine grid holds little but the cells that matter, and on a
// coarse one (triangles of a voxel or less) overlaps its neighbours' many
// times. A hierarchy query cost about twelve point-triangle distances on the
// armadillo (measured at --res 128, 256, 512).
size_t exactBandDistances(const TriangleBvh& bvh, const GridFrame& frame, const BandCells& cells, double bandVoxels,
                          std::vector<float>& distance, std::vector<uint32_t>& nearest, Progress* progress,
                          double progressWeight)
{
  constexpr double distancesPerQuery = 12.0;
  if (triangleNeighbourhoods(bvh, frame, bandVoxels) < distancesPerQuery * double(cells.count()))
    return exactBandByTriangles(bvh, frame, cells, bandVoxels, distance, nearest, progress, progressWeight);
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
