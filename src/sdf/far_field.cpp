#include "lbmshape/sdf/far_field.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>

#include <omp.h>

#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/sdf/cell_space.hpp"

namespace lbmshape {
namespace {

constexpr uint8_t kPending = 0, kSettled = 1;
constexpr float kBucketWidth = 1.0f;  // voxels
constexpr uint64_t kNoOffer = std::numeric_limits<uint64_t>::max();

template <class T>
void gather(std::vector<T>& out, const std::vector<T>& local)
{
#pragma omp critical(lbmshape_far_field_gather)
  out.insert(out.end(), local.begin(), local.end());
}

// An offer is a squared distance (its float bits, which order as the values
// do for non-negative floats) and the triangle it comes from, packed so that
// one atomic minimum keeps the best, ties going to the lower triangle index.
uint64_t pack(float distance2, uint32_t triangle)
{
  return uint64_t(std::bit_cast<uint32_t>(distance2)) << 32 | triangle;
}
uint32_t offeredTriangle(uint64_t offer) { return uint32_t(offer); }

template <class T>
bool lower(T& slot, T value)
{
  std::atomic_ref<T> a(slot);
  T old = a.load(std::memory_order_relaxed);
  while (value < old)
    if (a.compare_exchange_weak(old, value, std::memory_order_relaxed)) return true;
  return false;
}

struct Push {
  uint32_t cell;
  uint32_t bucket;
};

// The indices of the bits set in `bits`, in increasing order, into `out`;
// the bits are cleared. Each thread takes a run of words, counted first so
// that it knows where its indices go.
void takeMarked(std::vector<uint64_t>& bits, std::vector<uint32_t>& out)
{
  const size_t words = bits.size();
  std::vector<size_t> before(size_t(omp_get_max_threads()) + 1, 0);
#pragma omp parallel
  {
    const size_t t = size_t(omp_get_thread_num()), n = size_t(omp_get_num_threads());
    const size_t from = words * t / n, to = words * (t + 1) / n;
    size_t count = 0;
    for (size_t w = from; w < to; ++w) count += size_t(std::popcount(bits[w]));
    before[t + 1] = count;
#pragma omp barrier
#pragma omp single
    {
      for (size_t k = 0; k < n; ++k) before[k + 1] += before[k];
      out.resize(before[n]);
    }
    size_t at = before[t];
    for (size_t w = from; w < to; ++w) {
      for (uint64_t x = bits[w]; x != 0; x &= x - 1) out[at++] = uint32_t(w * 64 + size_t(std::countr_zero(x)));
      bits[w] = 0;
    }
  }
}

template <class Cells>
size_t propagateIn(const Cells& space, const TriangleBvh& bvh, const GridFrame& frame, float* distance,
                   uint32_t* nearest, bool exact, double maxVoxels)
{
  const size_t cells = space.count();
  const double inverseVoxel = 1.0 / frame.voxel;
  std::vector<uint8_t> state(cells, kPending);
  std::vector<uint64_t> offer(cells, kNoOffer);
  std::vector<uint32_t> listed(cells, std::numeric_limits<uint32_t>::max());  // lowest bucket holding the cell
  size_t seeded = 0;
#pragma omp parallel for schedule(static) reduction(+ : seeded)
  for (size_t i = 0; i < cells; ++i)
    if (nearest[i] != TriangleBvh::kNoTriangle) state[i] = kSettled, ++seeded;
  if (seeded == cells || seeded == 0) return 0;
  size_t filled = 0;

  // buckets[b] lists the cells whose best offer is in [b, b + 1) bucket widths.
  std::vector<std::vector<uint32_t>> buckets;
  std::vector<Push> pushes;
  auto file = [&] {
    for (const Push& p : pushes) {
      if (p.bucket >= buckets.size()) buckets.resize(p.bucket + 1);
      buckets[p.bucket].push_back(p.cell);
    }
    pushes.clear();
  };
  // A settled cell offers each pending neighbour the distance from that
  // neighbour to its own closest point q on triangle t: an upper bound of
  // the neighbour's distance to t, and close to it.
  // (Measured in voxels from q in grid coordinates.)
  auto offerAround = [&](size_t i, const glm::ivec3& c, const glm::dvec3& q, uint32_t t, size_t floor,
                         std::vector<Push>& out) {
    const glm::dvec3 qInGrid = frame.toGrid(q);
    space.forEachNeighbour(i, c, [&](size_t j, const glm::ivec3& n) {
      if (state[j] != kPending) return;
      const glm::dvec3 gap = glm::dvec3(n) - qInGrid;
      const float d2 = float(glm::dot(gap, gap));
      if (!lower(offer[j], pack(d2, t))) return;
      const uint32_t bucket = uint32_t(std::max(floor, size_t(std::sqrt(d2) / kBucketWidth)));
      if (lower(listed[j], bucket)) out.push_back({uint32_t(j), bucket});
    });
  };
  const interrupt::Watch stop;  // the threads below are not the call's
#pragma omp parallel
  {
    std::vector<Push> local;
#pragma omp for schedule(dynamic, 1024) nowait
    for (size_t i = 0; i < cells; ++i) {
      if (state[i] != kSettled || (i % 4096 == 0 && stop.requested())) continue;
      const glm::ivec3 c = space.coords(i);
      bool open = false;
      space.forEachNeighbour(i, c, [&](size_t j, const glm::ivec3&) { open = open || state[j] == kPending; });
      if (!open) continue;
      const glm::dvec3 q = bvh.closestOnTriangle(frame.toWorld(glm::dvec3(c)), nearest[i]).point;
      offerAround(i, c, q, nearest[i], 0, local);
    }
    gather(pushes, local);
  }
  file();

  std::vector<uint32_t> batch;
  std::vector<uint64_t> marked((cells + 63) / 64, 0);  // a round's cells, one bit each
  // Buckets past maxVoxels are not settled: a cell whose best offer lies
  // beyond is measured against the offered triangle (below) but offers
  // nothing on. Offers exceed the distance they lead to by a tenth of a
  // voxel or so, so this finds every cell within maxVoxels that settling
  // the next bucket as well would (none of the 800k cells of that bucket
  // came within maxVoxels for the armadillo at 512^3) at a sixth of the
  // cost.
  const bool bounded = std::isfinite(maxVoxels);
  const size_t lastBucket = bounded ? size_t(maxVoxels / kBucketWidth) : SIZE_MAX;
  for (size_t b = 0; b < buckets.size() && b <= lastBucket; ++b) {
    while (!buckets[b].empty()) {
      interrupt::check("nothing was written");  // a round lasts a fraction of a second
      // Settle the bucket's pending cells whose best offer still falls in it.
      const std::vector<uint32_t>& entries = buckets[b];
      // A cell is listed in a bucket at most once (lower() lists it only
      // when its bucket drops): no two threads mark the same cell.
#pragma omp parallel for schedule(static)
      for (size_t k = 0; k < entries.size(); ++k) {
        const uint32_t i = entries[k];
        if (state[i] == kPending && listed[i] == b) {
          listed[i] = std::numeric_limits<uint32_t>::max() - 1;  // entries elsewhere are stale now
          std::atomic_ref<uint64_t>(marked[i / 64]).fetch_or(uint64_t(1) << (i % 64), std::memory_order_relaxed);
        }
      }
      // In index order, cells and the neighbours they offer to lie together
      // in memory: the settling below took half the time (armadillo --res
      // 512: 1.64 -> 0.95 s) where the bucket's order (that of the offers)
      // scattered its reads. Read off a bitmap rather than sorted: sorting
      // each round's cells took 0.4 s of a 256^3 morph's two fields.
      takeMarked(marked, batch);
      buckets[b].clear();
      for (uint32_t i : batch) state[i] = kSettled;
        // Each settles on the triangle of its best offer, measured exactly,
        // and offers its own closest point on.
#pragma omp parallel
      {
        std::vector<Push> local;
#pragma omp for schedule(dynamic, 64) nowait
        for (size_t k = 0; k < batch.size(); ++k) {
          const size_t i = batch[k];
          const glm::ivec3 c = space.coords(i);
          const uint32_t t = offeredTriangle(offer[i]);
          const TriangleBvh::Closest best = bvh.closestOnTriangle(frame.toWorld(glm::dvec3(c)), t);
          distance[i] = float(best.distance * inverseVoxel);
          nearest[i] = t;
          offerAround(i, c, best.point, t, b, local);
        }
        gather(pushes, local);
      }
      filled += batch.size();
      file();
    }
    std::vector<uint32_t>().swap(buckets[b]);
  }
  if (bounded) {
#pragma omp parallel for schedule(dynamic, 1024) reduction(+ : filled)
    for (size_t i = 0; i < cells; ++i) {
      if (state[i] != kPending || offer[i] == kNoOffer) continue;
      const uint32_t t = offeredTriangle(offer[i]);
      const double d = bvh.closestOnTriangle(frame.toWorld(glm::dvec3(space.coords(i))), t).distance * inverseVoxel;
      if (d >= maxVoxels) continue;
      distance[i] = float(d);
      nearest[i] = t;
      ++filled;
    }
  }

  if (exact) {
#pragma omp parallel for schedule(dynamic, 256)
    for (size_t i = 0; i < cells; ++i) {
      if (offer[i] == kNoOffer) continue;
      const glm::dvec3 p = frame.toWorld(glm::dvec3(space.coords(i)));
      const TriangleBvh::Closest c = bvh.closest(p, bvh.closestOnTriangle(p, nearest[i]).distance);
      distance[i] = float(c.distance * inverseVoxel);
      nearest[i] = c.triangle;
    }
  }
  return filled;
}

}  // namespace

size_t propagateFarField(const TriangleBvh& bvh, const GridFrame& frame, Volume& distance,
                         std::vector<uint32_t>& nearest, bool exact)
{
  return propagateIn(GridCells(frame.extent), bvh, frame, distance.data(), nearest.data(), exact,
                     std::numeric_limits<double>::infinity());
}

size_t propagateFarField(const TriangleBvh& bvh, const GridFrame& frame, const BandCells& cells,
                         std::vector<float>& distance, std::vector<uint32_t>& nearest, double maxVoxels)
{
  return propagateIn(cells, bvh, frame, distance.data(), nearest.data(), false, maxVoxels);
}

}  // namespace lbmshape
