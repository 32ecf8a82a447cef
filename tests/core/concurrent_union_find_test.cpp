// ConcurrentUnionFind joined from many threads at once against the same
// joins made one after another: the same sets, each named by its lowest
// member.
#include <gtest/gtest.h>

#include <numeric>
#include <omp.h>
#include <random>
#include <vector>

#include "lbmshape/core/concurrent_union_find.hpp"

namespace lbmshape {
namespace {

// Plain union-find, one join at a time: each set's lowest member.
std::vector<uint32_t> lowestMembers(size_t count, const std::vector<std::pair<uint32_t, uint32_t>>& joins)
{
  std::vector<uint32_t> parent(count);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x];
    return x;
  };
  for (const auto& [a, b] : joins) {
    const uint32_t ra = find(a), rb = find(b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<uint32_t> lowest(count);
  for (size_t i = 0; i < count; ++i) lowest[i] = find(uint32_t(i));
  return lowest;
}

TEST(ConcurrentUnionFind, JoinsFromManyThreadsMakeTheSetsOfOneThread)
{
  constexpr size_t count = 200000;
  std::mt19937 rng(5);
  std::uniform_int_distribution<uint32_t> any(0, count - 1);
  // Joins near each other (long chains) and across (sets that merge late).
  std::vector<std::pair<uint32_t, uint32_t>> joins;
  for (size_t k = 0; k < count / 2; ++k) {
    const uint32_t a = any(rng);
    joins.emplace_back(a, std::min<uint32_t>(count - 1, a + 1 + rng() % 3));
    if (k % 50 == 0) joins.emplace_back(any(rng), any(rng));
  }
  const std::vector<uint32_t> expected = lowestMembers(count, joins);
  size_t sets = 0;
  for (size_t i = 0; i < count; ++i) sets += expected[i] == i;
  ASSERT_GT(sets, 100u);           // many sets
  ASSERT_LT(sets, count * 3 / 4);  // and many joined

  const int threads = omp_get_max_threads();
  omp_set_num_threads(std::max(threads, 4));
  ConcurrentUnionFind joined(count);
#pragma omp parallel for schedule(dynamic, 64)
  for (size_t k = 0; k < joins.size(); ++k) joined.unite(joins[k].first, joins[k].second);
  omp_set_num_threads(threads);
  EXPECT_EQ(std::move(joined).roots(), expected);
}

}  // namespace
}  // namespace lbmshape
