#include "sdf/winding_sign.hpp"

#include <cmath>
#include <limits>

#include "sdf/grid_blocks.hpp"

namespace lbmshape {
namespace {

constexpr int kBlock = 4;
// Accuracy assumed of one fast winding-number evaluation: twice the worst
// error seen (about 1e-3; see triangle_bvh.hpp and its tests).
constexpr float kEvaluationError = 2e-3f;
// Blocks where w may change by more than this per voxel gain nothing from
// propagation: their cells are all evaluated, in parallel, up front.
constexpr double kUsefulGrowth = 0.25;
// One voxel, with room for the float rounding of the stored distances.
constexpr float kOneVoxel = 1.0f + 1e-4f;

}  // namespace

std::vector<uint8_t> insideByWindingNumber(const TriangleBvh& bvh, const WindingGradientBound& gradient,
                                           const GridFrame& frame, const Volume& distance, size_t& evaluations)
{
  const Extent3 e = frame.extent;
  const size_t cells = e.cells();
  const GridBlocks blocks(e, kBlock);
  constexpr float kHopeless = std::numeric_limits<float>::infinity();

  // How much w may change over one step from a cell of each block: the
  // gradient bound over the block grown by one voxel (every step from the
  // block stays in there), times the step.
  std::vector<float> growth(blocks.count(), 0.0f);
  if (gradient.openEdgeCount() > 0) {
#pragma omp parallel for schedule(dynamic, 16)
    for (size_t b = 0; b < blocks.count(); ++b) {
      const CellRange r = blocks.range(b);
      const glm::dvec3 lo = frame.toWorld(glm::dvec3(r.x0 - 1, r.y0 - 1, r.z0 - 1));
      const glm::dvec3 hi = frame.toWorld(glm::dvec3(r.x1, r.y1, r.z1));
      const double g = gradient.over(lo, hi, kUsefulGrowth / frame.voxel) * frame.voxel;
      growth[b] = g > kUsefulGrowth ? kHopeless : float(g);
    }
  }

  std::vector<float> value(cells), radius(cells, -1.0f);  // radius < 0: not known yet
  size_t upFront = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : upFront)
  for (size_t b = 0; b < blocks.count(); ++b) {
    if (growth[b] != kHopeless) continue;
    const CellRange r = blocks.range(b);
    for (int z = r.z0; z < r.z1; ++z)
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
          const size_t i = e.index(x, y, z);
          value[i] = float(bvh.windingNumber(frame.cellCentre(x, y, z)));
          radius[i] = kEvaluationError;
          ++upFront;
        }
  }
  evaluations = upFront;

  auto evaluate = [&](size_t i) {
    value[i] = float(bvh.windingNumber(frame.cellCentre(int(i % e.nx), int(i / e.nx % e.ny), int(i / e.nx / e.ny))));
    radius[i] = kEvaluationError;
    ++evaluations;
  };
  // Breadth-first, so intervals widen with the path length from the
  // evaluated cell; every cell enters the queue once.
  std::vector<size_t> queue;
  queue.reserve(cells);
  size_t head = 0;
  const size_t stride[3] = {1, size_t(e.nx), size_t(e.nx) * e.ny};
  const int size[3] = {e.nx, e.ny, e.nz};
  auto flood = [&](size_t seed) {
    queue.push_back(seed);
    while (head < queue.size()) {
      const size_t i = queue[head++];
      const int c[3] = {int(i % e.nx), int(i / e.nx % e.ny), int(i / e.nx / e.ny)};
      const float widened = radius[i] + growth[blocks.blockOf(c[0], c[1], c[2])];
      const bool decided = std::abs(value[i] - 0.5f) > widened;
      for (int axis = 0; axis < 3; ++axis)
        for (int s = -1; s <= 1; s += 2) {
          if (c[axis] + s < 0 || c[axis] + s >= size[axis]) continue;
          const size_t j = s < 0 ? i - stride[axis] : i + stride[axis];
          // A surface point z on the segment would give d(i) + d(j) <=
          // |i - z| + |z - j| = one voxel.
          if (radius[j] >= 0.0f || !(distance[i] + distance[j] > kOneVoxel)) continue;
          if (decided)
            value[j] = value[i], radius[j] = widened;
          else
            evaluate(j);
          queue.push_back(j);
        }
    }
  };
  // The same test across the 26-neighbourhood, for a cell that the floods
  // did not reach: a cell hugging a surface that runs diagonally to the
  // grid has no face neighbour clear of it, but usually a diagonal one.
  auto inherit = [&](size_t i) {
    const int x = int(i % e.nx), y = int(i / e.nx % e.ny), z = int(i / e.nx / e.ny);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (!e.contains(x + dx, y + dy, z + dz)) continue;
          const size_t j = e.index(x + dx, y + dy, z + dz);
          if (radius[j] < 0.0f) continue;
          const float length = std::sqrt(float(dx * dx + dy * dy + dz * dz));
          const float widened = radius[j] + length * growth[blocks.blockOf(x + dx, y + dy, z + dz)];
          if (distance[i] + distance[j] > kOneVoxel * length && std::abs(value[j] - 0.5f) > widened) {
            value[i] = value[j], radius[i] = widened;
            return true;
          }
        }
    return false;
  };
  // Cells clear of the surface first: they flood the big regions, so that
  // the cells left over find decided neighbours.
  for (size_t seed = 0; seed < cells; ++seed)
    if (radius[seed] < 0.0f && distance[seed] > kOneVoxel) {
      evaluate(seed);
      flood(seed);
    }
  for (size_t seed = 0; seed < cells; ++seed)
    if (radius[seed] < 0.0f) {
      if (!inherit(seed)) evaluate(seed);
      flood(seed);
    }

  std::vector<uint8_t> inside(cells);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < cells; ++i) inside[i] = value[i] > 0.5f;
  return inside;
}

}  // namespace lbmshape
