// The regions of cells that no surface separates: two face neighbours
// belong together when the segment between them certainly misses the
// surface (the sum of their distances exceeds its length; see
// winding_sign.hpp). A closed surface's winding number is constant over
// such a region, so one evaluation signs all of it.
//
// Labelled by union-find on all threads at once (ConcurrentUnionFind),
// where a breadth-first flood visits the cells one after another: each
// region ends up named by its lowest cell, whatever order the threads joined
// its pieces in, so the labels do not depend on the thread count.
#pragma once

#include <atomic>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include <omp.h>

#include "lbmshape/core/concurrent_union_find.hpp"
#include "lbmshape/core/interrupt.hpp"

namespace lbmshape {

// For each cell, the lowest cell of its region. `distance` holds each
// cell's unsigned distance in voxels (as winding_sign.hpp requires);
// `segment` is the neighbours' spacing, in voxels, with room for rounding.
template <class Cells>
std::vector<uint32_t> clearRegions(const Cells& cells, const float* distance, float segment)
{
  const size_t count = cells.count();
  if (count > std::numeric_limits<uint32_t>::max()) throw std::length_error("too many cells for the sign's regions");
  ConcurrentUnionFind regions(count);

  // Each thread takes one contiguous run of cells and first joins the pairs
  // that lie wholly within it: their roots stay within its run, so no other
  // thread writes there. The pairs that cross into another run wait in the
  // thread's list until every run is joined: by then nearly every such pair
  // finds its two cells' roots already one (a read of a shared line), and
  // only the few joins of one run's regions to another's write. Joining
  // every pair at once, in chunks handed out as threads came free, sent
  // every thread's writes to the roots of the one region that holds nearly
  // every cell of a morph's band.
  std::atomic<bool> interrupted = false;
  const interrupt::Watch stop;  // the threads below are not the call's
#pragma omp parallel
  {
    const size_t threads = size_t(omp_get_num_threads()), thread = size_t(omp_get_thread_num());
    const size_t begin = count * thread / threads, end = count * (thread + 1) / threads;
    std::vector<std::pair<uint32_t, uint32_t>> crossing;  // joined after the barrier
    for (size_t i = begin; i < end; ++i) {
      if ((i - begin) % 65536 == 0 && stop.requested()) interrupted = true;
      if (interrupted.load(std::memory_order_relaxed)) break;
      // Cells beyond the grid (the band's bricks overhang it) stay alone,
      // as the flood never reaches them.
      if (!cells.real(i)) continue;
      cells.forEachFaceNeighbour(i, cells.coords(i), [&](size_t j) {
        // Each pair once, from its lower cell; !(a > b) also refuses NaN.
        if (j <= i || !(distance[i] + distance[j] > segment)) return;
        if (j < end)
          regions.unite(uint32_t(i), uint32_t(j));
        else
          crossing.emplace_back(uint32_t(i), uint32_t(j));
      });
    }
#pragma omp barrier
    for (const auto& [i, j] : crossing) regions.unite(i, j);
  }
  if (interrupted) interrupt::check("nothing was written");
  return std::move(regions).roots();
}

}  // namespace lbmshape
