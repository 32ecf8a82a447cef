// Union-find that many threads may join at once, lock-free: a forest of
// parent links over the numbers [0, n), each link pointing to a lower
// number. A join links the higher root under the lower by compare-exchange
// and starts again if another thread changed that root meanwhile; a find
// halves its path (each number pointed at its grandparent) on the way.
// Concurrent finds and joins only ever replace a parent by one of its
// ancestors, so no cycle can form, and when the joins are done each set's
// root is its lowest member, whatever order the threads joined in.
#pragma once

#include <atomic>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace lbmshape {

class ConcurrentUnionFind {
public:
  explicit ConcurrentUnionFind(size_t count) : parent_(count)
  {
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < count; ++i) parent_[i] = uint32_t(i);
  }

  uint32_t find(uint32_t x)
  {
    for (;;) {
      std::atomic_ref<uint32_t> link(parent_[x]);
      uint32_t p = link.load(std::memory_order_relaxed);
      if (p == x) return x;
      const uint32_t grandparent = std::atomic_ref<uint32_t>(parent_[p]).load(std::memory_order_relaxed);
      if (grandparent != p) link.compare_exchange_weak(p, grandparent, std::memory_order_relaxed);
      x = grandparent;
    }
  }

  void unite(uint32_t a, uint32_t b)
  {
    for (;;) {
      a = find(a);
      b = find(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);
      uint32_t expected = a;
      if (std::atomic_ref<uint32_t>(parent_[a]).compare_exchange_strong(expected, b, std::memory_order_relaxed)) return;
    }
  }

  // After the joins (not during them): each number's root, the lowest
  // member of its set, the links replaced by them.
  std::vector<uint32_t> roots() &&
  {
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < parent_.size(); ++i) {
      const uint32_t root = find(uint32_t(i));
      std::atomic_ref<uint32_t>(parent_[i]).store(root, std::memory_order_relaxed);
    }
    return std::move(parent_);
  }

private:
  std::vector<uint32_t> parent_;
};

}  // namespace lbmshape
