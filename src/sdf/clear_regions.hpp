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
#include <vector>

#include "core/concurrent_union_find.hpp"
#include "core/interrupt.hpp"

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

  std::atomic<bool> interrupted = false;
#pragma omp parallel for schedule(dynamic, 4096)
  for (size_t i = 0; i < count; ++i) {
    if (i % 65536 == 0 && interrupt::requested()) interrupted = true;
    // Cells beyond the grid (the band's bricks overhang it) stay alone,
    // as the flood never reaches them.
    if (interrupted.load(std::memory_order_relaxed) || !cells.real(i)) continue;
    cells.forEachFaceNeighbour(i, cells.coords(i), [&](size_t j) {
      // Each pair once, from its lower cell; !(a > b) also refuses NaN.
      if (j > i && distance[i] + distance[j] > segment) regions.unite(uint32_t(i), uint32_t(j));
    });
  }
  if (interrupted) interrupt::check("nothing was written");
  return std::move(regions).roots();
}

}  // namespace lbmshape
