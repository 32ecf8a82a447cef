#include "lbmshape/sdf/winding_sign.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/sdf/cell_space.hpp"
#include "lbmshape/sdf/clear_regions.hpp"

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

// One fast winding-number evaluation at cell i (within kEvaluationError).
template <class Cells>
float windingAt(const Cells& cells, const TriangleBvh& bvh, const GridFrame& frame, size_t i)
{
  return float(bvh.windingNumber(frame.toWorld(glm::dvec3(cells.coords(i)))));
}

// The flood's first part for a closed surface, where w does not change
// along a certified segment (no growth anywhere): every cell of a region
// takes the value of the region's first cell more than a voxel from the
// surface, as the flood started from that cell would hand it on. Returns
// false, having changed no cell, if one of those values is too near 1/2 to
// hand on; the flood then decides.
template <class Cells>
bool signRegionsAtOnce(const Cells& cells, const TriangleBvh& bvh, const GridFrame& frame, const float* distance,
                       std::vector<float>& value, std::vector<float>& radius, size_t& evaluations)
{
  const size_t count = cells.count();
  const std::vector<uint32_t> region = clearRegions(cells, distance, kOneVoxel);

  // Each region's seed: its lowest cell that the flood would seed from.
  std::unordered_map<uint32_t, uint32_t> seedOf;
#pragma omp parallel
  {
    std::unordered_map<uint32_t, uint32_t> local;
    uint32_t last = UINT32_MAX;  // consecutive cells mostly share a region
#pragma omp for schedule(static) nowait
    for (size_t i = 0; i < count; ++i) {
      if (region[i] == last || !(distance[i] > kOneVoxel) || !cells.real(i)) continue;
      last = region[i];
      local.try_emplace(last, uint32_t(i));  // a thread's cells come in rising order
    }
#pragma omp critical(lbmshape_sign_regions)
    for (const auto& [r, seed] : local) {
      const auto [it, added] = seedOf.try_emplace(r, seed);
      if (!added) it->second = std::min(it->second, seed);
    }
  }
  std::vector<std::pair<uint32_t, uint32_t>> seeds(seedOf.begin(), seedOf.end());
  std::vector<float> seedValue(seeds.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (size_t k = 0; k < seeds.size(); ++k) seedValue[k] = windingAt(cells, bvh, frame, seeds[k].second);
  evaluations += seeds.size();
  for (float v : seedValue)
    if (!(std::abs(v - 0.5f) > kEvaluationError)) return false;

  // The root (the region's lowest cell) holds the region's value; then every
  // other cell of a seeded region copies it.
  for (size_t k = 0; k < seeds.size(); ++k)
    value[seeds[k].first] = seedValue[k], radius[seeds[k].first] = kEvaluationError;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < count; ++i) {
    const uint32_t r = region[i];
    if (r != i && radius[r] >= 0.0f) value[i] = value[r], radius[i] = radius[r];
  }
  return true;
}

template <class Cells>
std::vector<uint8_t> insideFlood(const Cells& cells, const TriangleBvh& bvh, const WindingGradientBound& gradient,
                                 const GridFrame& frame, const float* distance, size_t& evaluations)
{
  const size_t count = cells.count();
  constexpr float kHopeless = std::numeric_limits<float>::infinity();

  // How much w may change over one step from a cell of each block: the
  // gradient bound over the block grown by one voxel (every step from the
  // block stays in there), times the step.
  std::vector<float> growth(cells.blockCount(), 0.0f);
  if (gradient.openEdgeCount() > 0) {
#pragma omp parallel for schedule(dynamic, 16)
    for (size_t b = 0; b < cells.blockCount(); ++b) {
      glm::ivec3 lo, hi;
      cells.blockRange(b, lo, hi);
      const double g =
          gradient.over(frame.toWorld(glm::dvec3(lo - 1)), frame.toWorld(glm::dvec3(hi)), kUsefulGrowth / frame.voxel) *
          frame.voxel;
      growth[b] = g > kUsefulGrowth ? kHopeless : float(g);
    }
  }

  std::vector<float> value(count), radius(count, -1.0f);  // radius < 0: not known yet
  size_t upFront = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : upFront)
  for (size_t b = 0; b < cells.blockCount(); ++b) {
    if (growth[b] != kHopeless) continue;
    cells.forEachCellOf(b, [&](size_t i, const glm::ivec3& c) {
      value[i] = float(bvh.windingNumber(frame.toWorld(glm::dvec3(c))));
      radius[i] = kEvaluationError;
      ++upFront;
    });
  }
  evaluations = upFront;

  auto evaluate = [&](size_t i) {
    value[i] = windingAt(cells, bvh, frame, i);
    radius[i] = kEvaluationError;
    ++evaluations;
  };
  // The same for a list of cells (any vector of indices), on every thread.
  auto evaluateAll = [&](const auto& list) {
#pragma omp parallel for schedule(dynamic, 16) if (list.size() >= 64)
    for (size_t k = 0; k < list.size(); ++k) {
      value[list[k]] = windingAt(cells, bvh, frame, list[k]);
      radius[list[k]] = kEvaluationError;
    }
    evaluations += list.size();
  };
  // Breadth-first, so intervals widen with the path length from the
  // evaluated cell; every cell enters the queue once. Level by level: a
  // cell reached from an undecided one is marked known at once (no other
  // cell hands it a value) and evaluated with the rest of its level, on
  // every thread, before the next level reads it, which is when the queue
  // would have reached it; so the values are the one-at-a-time flood's,
  // whatever the threads. (An open scan's flood evaluates tens of
  // thousands of cells: 79,147 for bunny_scan at --res 128, 0.5-0.6 s on
  // one thread.)
  if (count > std::numeric_limits<uint32_t>::max()) throw std::length_error("too many cells for the sign's flood");
  std::vector<uint32_t> queue, toEvaluate;
  size_t head = 0;
  auto flood = [&](size_t seed) {
    queue.push_back(uint32_t(seed));
    while (head < queue.size()) {
      for (const size_t levelEnd = queue.size(); head < levelEnd;) {
        if (head % 65536 == 0) interrupt::check("nothing was written");
        const size_t i = queue[head++];
        const glm::ivec3 c = cells.coords(i);
        const float widened = radius[i] + growth[cells.blockOf(i)];
        const bool decided = std::abs(value[i] - 0.5f) > widened;
        cells.forEachFaceNeighbour(i, c, [&](size_t j) {
          // A surface point z on the segment would give d(i) + d(j) <=
          // |i - z| + |z - j| = one voxel.
          if (radius[j] >= 0.0f || !(distance[i] + distance[j] > kOneVoxel)) return;
          if (decided) {
            value[j] = value[i], radius[j] = widened;
          } else {
            radius[j] = kEvaluationError;
            toEvaluate.push_back(uint32_t(j));
          }
          queue.push_back(uint32_t(j));
        });
      }
      evaluateAll(toEvaluate);
      toEvaluate.clear();
    }
  };
  // Cells clear of the surface first: they flood the big regions (one
  // evaluation each). A closed surface's regions are labelled on all
  // threads at once, with the same result; otherwise (or where a region's
  // evaluation falls too near 1/2 to hand on) the flood goes sequentially,
  // since a region may span the grid.
  if (gradient.openEdgeCount() > 0 || !signRegionsAtOnce(cells, bvh, frame, distance, value, radius, evaluations)) {
    queue.reserve(count);
    for (size_t seed = 0; seed < count; ++seed)
      if (radius[seed] < 0.0f && cells.real(seed) && distance[seed] > kOneVoxel) {
        evaluate(seed);
        flood(seed);
      }
  }

  // The cells left hug the surface. Each takes the value of a decided
  // neighbour across its 26-neighbourhood where the same test allows it (a
  // surface that runs diagonally to the grid leaves a cell no face
  // neighbour clear of it, but usually a diagonal one), in rounds that read
  // only what earlier rounds decided, so the cells of a round are
  // independent; the few that no neighbour decides are evaluated, all in
  // parallel.
  std::vector<size_t> left;
  for (size_t i = 0; i < count; ++i)
    if (radius[i] < 0.0f && cells.real(i)) left.push_back(i);
  struct Inherited {
    float value, radius;
  };
  std::vector<Inherited> taken(left.size());
  auto inherit = [&](size_t i, Inherited& out) {
    const glm::ivec3 c = cells.coords(i);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const size_t j = cells.neighbour(i, c, glm::ivec3(dx, dy, dz));
          if (j == noCell || radius[j] < 0.0f) continue;
          const float length = std::sqrt(float(dx * dx + dy * dy + dz * dz));
          const float widened = radius[j] + length * growth[cells.blockOf(j)];
          if (distance[i] + distance[j] > kOneVoxel * length && std::abs(value[j] - 0.5f) > widened) {
            out = {value[j], widened};
            return true;
          }
        }
    return false;
  };
  while (!left.empty()) {
    std::vector<uint8_t> decided(left.size(), 0);
#pragma omp parallel for schedule(dynamic, 256)
    for (size_t k = 0; k < left.size(); ++k) decided[k] = inherit(left[k], taken[k]);
    size_t kept = 0;
    for (size_t k = 0; k < left.size(); ++k) {
      if (decided[k])
        value[left[k]] = taken[k].value, radius[left[k]] = taken[k].radius;
      else
        left[kept++] = left[k];
    }
    const bool progress = kept < left.size();
    left.resize(kept);
    if (!progress) break;
  }
  evaluateAll(left);

  std::vector<uint8_t> inside(count);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < count; ++i) inside[i] = value[i] > 0.5f;
  return inside;
}

}  // namespace

std::vector<uint8_t> insideByWindingNumber(const TriangleBvh& bvh, const WindingGradientBound& gradient,
                                           const GridFrame& frame, const Volume& distance, size_t& evaluations)
{
  return insideFlood(GridCells(frame.extent, kBlock), bvh, gradient, frame, distance.data(), evaluations);
}

std::vector<uint8_t> insideByWindingNumber(const TriangleBvh& bvh, const WindingGradientBound& gradient,
                                           const GridFrame& frame, const BandCells& cells,
                                           const std::vector<float>& distance, size_t& evaluations)
{
  return insideFlood(cells, bvh, gradient, frame, distance.data(), evaluations);
}

}  // namespace lbmshape
