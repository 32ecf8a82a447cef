#include "lbmshape/sdf/band_distance.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>

#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/sdf/cell_space.hpp"
#include "lbmshape/sdf/point_triangle.hpp"

namespace lbmshape {

namespace {

// A block of cells that may hold one within the band, with a triangle near
// it (the first hint of its cells' searches).
struct NearBlock {
  size_t block;
  uint32_t triangle;
};

// The blocks with a cell within `bandVoxels` of the surface, and maybe a few
// more. Every cell of a block is within halfDiagonal of its centre, so when
// no triangle is within band + halfDiagonal of the centre, no cell of the
// block is within band of the surface: most blocks of a grid, and of a
// morph's band the bricks near the other mesh alone, end here.
// With `stride` > 1, of every stride-th block only.
template <class Cells>
std::vector<NearBlock> blocksNearSurface(const Cells& cells, const TriangleBvh& bvh, const GridFrame& frame,
                                         double bandVoxels, size_t stride = 1)
{
  const double band = bandVoxels * frame.voxel;
  std::vector<uint32_t> found(cells.blockCount(), TriangleBvh::kNoTriangle);
  const interrupt::Watch stop;  // the threads below are not the call's
#pragma omp parallel for schedule(dynamic, 16)
  for (size_t b = 0; b < cells.blockCount(); b += stride) {
    if (b % 256 == 0 && stop.requested()) continue;  // the caller stops after the loop
    glm::ivec3 lo, hi;
    cells.blockRange(b, lo, hi);
    const glm::dvec3 first(lo), last(hi - 1);
    const glm::dvec3 centre = frame.toWorld(0.5 * (first + last));
    const double halfDiagonal = 0.5 * frame.voxel * glm::length(last - first);
    found[b] = bvh.closest(centre, band + halfDiagonal).triangle;
  }
  std::vector<NearBlock> near;
  for (size_t b = 0; b < found.size(); ++b)
    if (found[b] != TriangleBvh::kNoTriangle) near.push_back({b, found[b]});
  return near;
}

// Cell by cell in the blocks near the surface, asking the hierarchy.
template <class Cells>
size_t exactBandDistancesIn(const Cells& cells, const std::vector<NearBlock>& near, const TriangleBvh& bvh,
                            const GridFrame& frame, double bandVoxels, float* distance, uint32_t* nearest,
                            Progress* progress, double progressWeight)
{
  if (progress) progress->beginPart("exact band", double(near.size()), progressWeight);
  const double band = bandVoxels * frame.voxel;
  size_t written = 0;
  const interrupt::Watch stop;  // the threads below are not the call's
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : written)
  for (size_t k = 0; k < near.size(); ++k) {
    if (stop.requested()) continue;  // the caller stops after the loop
    if (progress) progress->advance();
    uint32_t hint = near[k].triangle;
    cells.forEachCellOf(near[k].block, [&](size_t i, const glm::ivec3& c) {
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
  const GridCells cells(frame.extent, 8);
  return exactBandDistancesIn(cells, blocksNearSurface(cells, bvh, frame, bandVoxels), bvh, frame, bandVoxels,
                              distance.data(), nearest.data(), progress, progressWeight);
}

namespace {

// What a triangle reaches, in grid coordinates: the cells within `band`
// voxels of it lie in the ball around its centroid of the farthest
// corner's distance plus the band, within the box around its corners grown
// by the band, and within the band of its plane.
struct TriangleReach {
  TriangleReach(const TriangleBvh& bvh, const GridFrame& frame, uint32_t triangle, double bandVoxels)
  {
    glm::dvec3 a, b, c;
    bvh.triangleCorners(triangle, a, b, c);
    a = frame.toGrid(a), b = frame.toGrid(b), c = frame.toGrid(c);
    centre = (a + b + c) / 3.0;
    radius = std::sqrt(std::max({glm::dot(a - centre, a - centre), glm::dot(b - centre, b - centre),
                                 glm::dot(c - centre, c - centre)})) +
             bandVoxels;
    lo = glm::max(glm::min(a, glm::min(b, c)), centre - radius) - bandVoxels;
    hi = glm::min(glm::max(a, glm::max(b, c)), centre + radius) + bandVoxels;
    normal = glm::cross(b - a, c - a);
    const double length = glm::length(normal);
    // A sliver's normal is noise: it keeps the ball and the box alone.
    planeTest = length > 1e-12 * std::max(1.0, glm::dot(b - a, b - a) + glm::dot(c - a, c - a));
    normal = planeTest ? normal / length : glm::dvec3(0.0);
    offset = glm::dot(normal, a);
    band = bandVoxels;
  }

  // The cells of row (y, z) the ball spans, as [x0, x1]; empty when x0 > x1.
  void row(int y, int z, int& x0, int& x1) const
  {
    const double dy = y - centre.y, dz = z - centre.z, rest = radius * radius - dy * dy - dz * dz;
    if (rest < 0.0) {
      x0 = 1, x1 = 0;
      return;
    }
    const double half = std::sqrt(rest);
    x0 = int(std::ceil(centre.x - half)), x1 = int(std::floor(centre.x + half));
  }
  bool nearPlane(int x, int y, int z) const
  {
    return !planeTest || std::abs(glm::dot(normal, glm::dvec3(x, y, z)) - offset) <= band;
  }
  // Work: the cells of the ball within the box, about.
  double cells() const
  {
    const glm::dvec3 box = glm::max(hi - lo, 0.0);
    return std::min(box.x * box.y * box.z, 4.19 * radius * radius * radius);
  }

  glm::dvec3 centre, lo, hi, normal;
  double radius, offset, band;
  bool planeTest;
};

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
  const double band = bandVoxels * frame.voxel, band2 = band * band;
  const double halfDiagonal = 0.5 * (brickEdge - 1) * std::sqrt(3.0) * frame.voxel;
  const interrupt::Watch stop;  // the threads below are not the call's
#pragma omp parallel for schedule(dynamic, 256)
  for (size_t t = 0; t < count; ++t) {
    if (stop.requested()) continue;  // the caller stops after the loop
    if (progress && t % 256 == 0) progress->advance(256);
    const uint32_t triangle = uint32_t(t);
    const TriangleReach reach(bvh, frame, triangle, bandVoxels);
    glm::dvec3 a, b, c;
    bvh.triangleCorners(triangle, a, b, c);
    const PreparedTriangle prepared(a, b, c);
    const glm::ivec3 first = glm::max(glm::ivec3(glm::ceil(reach.lo)), glm::ivec3(0));
    const glm::ivec3 last = glm::min(glm::ivec3(glm::floor(reach.hi)), glm::ivec3(e.nx - 1, e.ny - 1, e.nz - 1));
    if (glm::any(glm::lessThan(last, first))) continue;
    const glm::ivec3 firstBrick = first / brickEdge, lastBrick = last / brickEdge;
    for (int bz = firstBrick.z; bz <= lastBrick.z; ++bz)
      for (int by = firstBrick.y; by <= lastBrick.y; ++by)
        for (int bx = firstBrick.x; bx <= lastBrick.x; ++bx) {
          const int32_t slot = bricks.slot(bx, by, bz);
          if (slot == noBrick) continue;
          const glm::ivec3 origin = brickEdge * glm::ivec3(bx, by, bz);
          const glm::dvec3 centre = frame.toWorld(glm::dvec3(origin) + 0.5 * (brickEdge - 1));
          if (prepared.distance2(centre) > (band + halfDiagonal) * (band + halfDiagonal)) continue;
          const glm::ivec3 from = glm::max(first, origin), to = glm::min(last, origin + brickEdge - 1);
          for (int z = from.z; z <= to.z; ++z)
            for (int y = from.y; y <= to.y; ++y) {
              int x0, x1;
              reach.row(y, z, x0, x1);
              for (int x = std::max(x0, from.x); x <= std::min(x1, to.x); ++x) {
                if (!reach.nearPlane(x, y, z)) continue;
                const double d2 = prepared.distance2(frame.cellCentre(x, y, z));
                if (d2 > band2) continue;
                const size_t i = size_t(slot) * brickCells + size_t(cellInBrick(x & 7, y & 7, z & 7));
                const float v = float(std::sqrt(d2) / frame.voxel);
                const uint64_t packed = uint64_t(std::bit_cast<uint32_t>(v)) << 32 | triangle;
                std::atomic_ref<uint64_t> slotBest(best[i]);
                uint64_t old = slotBest.load(std::memory_order_relaxed);
                while (packed < old && !slotBest.compare_exchange_weak(old, packed, std::memory_order_relaxed)) {}
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

// Cells the triangles reach, summed over the triangles: the work of
// exactBandByTriangles.
double triangleNeighbourhoods(const TriangleBvh& bvh, const GridFrame& frame, double bandVoxels)
{
  double cells = 0.0;
  for (uint32_t t = 0; t < bvh.triangleCount(); ++t) cells += TriangleReach(bvh, frame, t, bandVoxels).cells();
  return cells;
}

}  // namespace

// On the band, the cheaper of two ways. Asking the hierarchy cell by cell
// asks about every cell of the bricks near the surface, most of them
// farther than the band; going triangle by triangle visits each triangle's
// neighbourhood, which on a fine grid holds little but the cells that
// matter, and on a coarse one (triangles of a voxel or less) overlaps its
// neighbours' many times. Only the bricks near the surface count: a
// morph's band holds both meshes' and those between. Measured on the
// armadillo and the sphere, a query of a cell near the surface cost 13 to
// 52 point-triangle distances (denoise at 256^3, the sphere and the
// armadillo of a morph at 128^3 and 256^3); 24 picks the faster way in all
// five (the armadillo of the morph at 128^3: 48 ms where the triangles
// took 155).
size_t exactBandDistances(const TriangleBvh& bvh, const GridFrame& frame, const BandCells& cells, double bandVoxels,
                          std::vector<float>& distance, std::vector<uint32_t>& nearest, Progress* progress,
                          double progressWeight)
{
  constexpr double distancesPerQuery = 24.0;
  // How many bricks are near, from every 16th: a denoise's band is near its
  // surface throughout, and counting them all would cost it a query a brick
  // when it goes by triangles.
  constexpr size_t stride = 16;
  const size_t sampled = (cells.blockCount() + stride - 1) / stride;
  const double nearFraction =
      double(blocksNearSurface(cells, bvh, frame, bandVoxels, stride).size()) / double(std::max<size_t>(sampled, 1));
  interrupt::check("nothing was written");
  if (triangleNeighbourhoods(bvh, frame, bandVoxels) < distancesPerQuery * nearFraction * double(cells.count()))
    return exactBandByTriangles(bvh, frame, cells, bandVoxels, distance, nearest, progress, progressWeight);
  const std::vector<NearBlock> near = blocksNearSurface(cells, bvh, frame, bandVoxels);
  interrupt::check("nothing was written");
  return exactBandDistancesIn(cells, near, bvh, frame, bandVoxels, distance.data(), nearest.data(), progress,
                              progressWeight);
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
      const TriangleBvh::Closest c =
          hint == TriangleBvh::kNoTriangle ? bvh.closest(p) : bvh.closest(p, bvh.closestOnTriangle(p, hint).distance);
      distance[i] = float(c.distance / frame.voxel);
      nearest[i] = hint = c.triangle;
      ++written;
    }
  }
  return written;
}

}  // namespace lbmshape
