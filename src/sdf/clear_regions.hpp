// The regions of cells that no surface separates: two face neighbours
// belong together when the segment between them certainly misses the
// surface (the sum of their distances exceeds its length; see
// winding_sign.hpp). A closed surface's winding number is constant over
// such a region, so one evaluation signs all of it.
//
// Labelled by union-find on all threads at once, where a breadth-first
// flood visits the cells one after another: each region ends up named by its
// lowest cell, whatever order the threads joined its pieces in, so the
// labels do not depend on the thread count.
#pragma once

#include <atomic>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/interrupt.hpp"

namespace lbmshape {
namespace clear_regions_detail {

// The root of x's tree, halving the path on the way (each cell pointed at
// its grandparent): concurrent finds and links only ever replace a parent by
// one of its ancestors, so every link points to a lower cell and no cycle
// can form.
inline uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t x)
{
  for (;;) {
    std::atomic_ref<uint32_t> link(parent[x]);
    uint32_t p = link.load(std::memory_order_relaxed);
    if (p == x) return x;
    const uint32_t grandparent = std::atomic_ref<uint32_t>(parent[p]).load(std::memory_order_relaxed);
    if (grandparent != p) link.compare_exchange_weak(p, grandparent, std::memory_order_relaxed);
    x = grandparent;
  }
}

// Joins the trees of a and b, the higher root under the lower; a root
// changed meanwhile by another thread makes the compare-exchange fail and
// the join start again from the new roots.
inline void unite(std::vector<uint32_t>& parent, uint32_t a, uint32_t b)
{
  for (;;) {
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a == b) return;
    if (a < b) std::swap(a, b);
    uint32_t expected = a;
    if (std::atomic_ref<uint32_t>(parent[a]).compare_exchange_strong(expected, b, std::memory_order_relaxed)) return;
  }
}

}  // namespace clear_regions_detail

// For each cell, the lowest cell of its region. `distance` holds each
// cell's unsigned distance in voxels (as winding_sign.hpp requires);
// `segment` is the neighbours' spacing, in voxels, with room for rounding.
template <class Cells>
std::vector<uint32_t> clearRegions(const Cells& cells, const float* distance, float segment)
{
  using namespace clear_regions_detail;
  const size_t count = cells.count();
  if (count > std::numeric_limits<uint32_t>::max()) throw std::length_error("too many cells for the sign's regions");
  std::vector<uint32_t> parent(count);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < count; ++i) parent[i] = uint32_t(i);

  std::atomic<bool> interrupted = false;
#pragma omp parallel for schedule(dynamic, 4096)
  for (size_t i = 0; i < count; ++i) {
    if (i % 65536 == 0 && interrupt::requested()) interrupted = true;
    // Cells beyond the grid (the band's bricks overhang it) stay alone,
    // as the flood never reaches them.
    if (interrupted.load(std::memory_order_relaxed) || !cells.real(i)) continue;
    cells.forEachFaceNeighbour(i, cells.coords(i), [&](size_t j) {
      // Each pair once, from its lower cell; !(a > b) also refuses NaN.
      if (j > i && distance[i] + distance[j] > segment) unite(parent, uint32_t(i), uint32_t(j));
    });
  }
  if (interrupted) interrupt::check("nothing was written");

#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < count; ++i) {
    // Every cell straight to its root: the regions' names.
    const uint32_t root = findRoot(parent, uint32_t(i));
    std::atomic_ref<uint32_t>(parent[i]).store(root, std::memory_order_relaxed);
  }
  return parent;
}

}  // namespace lbmshape
