// clearRegions (union-find on all threads) against a breadth-first flood
// on one thread, on random distances that cut the cells into many regions
// of every shape, over a whole grid and over a band's scattered bricks.
#include <gtest/gtest.h>

#include <omp.h>
#include <queue>
#include <random>

#include "lbmshape/sdf/cell_space.hpp"
#include "lbmshape/sdf/clear_regions.hpp"

namespace lbmshape {
namespace {

constexpr float kSegment = 1.0f;

// Distances that join about half the neighbour pairs (percolation near its
// threshold: regions from single cells to most of the grid), and infinity
// for a few cells, as beyond the band.
std::vector<float> randomDistances(size_t count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> d(count);
  for (float& v : d) v = u(rng) < 0.01f ? std::numeric_limits<float>::infinity() : u(rng);
  return d;
}

// The oracle: regions flooded one after another, from their lowest cell.
template <class Cells>
std::vector<uint32_t> floodedRegions(const Cells& cells, const std::vector<float>& d)
{
  const size_t count = cells.count();
  std::vector<uint32_t> label(count, UINT32_MAX);
  for (size_t seed = 0; seed < count; ++seed) {
    if (label[seed] != UINT32_MAX) continue;
    label[seed] = uint32_t(seed);
    if (!cells.real(seed)) continue;
    std::queue<size_t> open;
    open.push(seed);
    while (!open.empty()) {
      const size_t i = open.front();
      open.pop();
      cells.forEachFaceNeighbour(i, cells.coords(i), [&](size_t j) {
        if (label[j] == UINT32_MAX && d[i] + d[j] > kSegment) label[j] = uint32_t(seed), open.push(j);
      });
    }
  }
  return label;
}

template <class Cells>
void expectRegionsOfTheFlood(const Cells& cells, unsigned seed)
{
  const std::vector<float> d = randomDistances(cells.count(), seed);
  const std::vector<uint32_t> expected = floodedRegions(cells, d);
  size_t regions = 0, joined = 0;
  for (size_t i = 0; i < expected.size(); ++i) regions += expected[i] == i, joined += expected[i] != i;
  // The field must make a test: many regions, and many cells joined.
  ASSERT_GT(regions, 100u);
  ASSERT_GT(joined, expected.size() / 4);

  const int threads = omp_get_max_threads();
  for (int t : {1, std::max(threads, 4)}) {
    omp_set_num_threads(t);
    const std::vector<uint32_t> labels = clearRegions(cells, d.data(), kSegment);
    ASSERT_EQ(labels.size(), expected.size());
    for (size_t i = 0; i < labels.size(); ++i)
      ASSERT_EQ(labels[i], expected[i]) << "cell " << i << " with " << t << " threads";
  }
  omp_set_num_threads(threads);
}

TEST(ClearRegions, AreTheFloodsRegionsOnAGrid)
{
  for (unsigned seed : {1u, 2u, 3u}) expectRegionsOfTheFlood(GridCells(Extent3{37, 29, 23}), seed);
}

TEST(ClearRegions, AreTheFloodsRegionsOnScatteredBricks)
{
  // Sides that are not multiples of 8 (bricks overhang the grid: cells that
  // are not real must stay alone), and bricks with and without neighbours.
  BrickSet bricks(Extent3{45, 38, 30});
  std::mt19937 rng(7);
  for (int z = 0; z < bricks.bricks().nz; ++z)
    for (int y = 0; y < bricks.bricks().ny; ++y)
      for (int x = 0; x < bricks.bricks().nx; ++x)
        if (rng() % 3 != 0) bricks.activate(x, y, z);
  const BandCells cells(bricks);
  for (unsigned seed : {4u, 5u}) expectRegionsOfTheFlood(cells, seed);
}

TEST(ClearRegions, NameEachRegionByItsLowestCell)
{
  // A wall of cells on the surface (distance 0) across x = 5 of a 12 x 4 x 4
  // grid.
  const Extent3 e{12, 4, 4};
  std::vector<float> d(e.cells(), 3.0f);
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y) d[e.index(5, y, z)] = 0.0f;
  const std::vector<uint32_t> labels = clearRegions(GridCells(e), d.data(), kSegment);
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y)
      for (int x = 0; x < e.nx; ++x) {
        const size_t i = e.index(x, y, z);
        // 0 + 3 > 1: a wall cell still joins its neighbours, as the flood
        // would hand its sign on across; only two wall cells together are
        // not certified.
        EXPECT_EQ(labels[i], 0u) << x << "," << y << "," << z;
      }
  // Two cells thick, the wall divides; the cells of x = 5 still join the
  // left side, those of x = 7 (at 0.5) the right.
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y) d[e.index(5, y, z)] = d[e.index(6, y, z)] = 0.0f, d[e.index(7, y, z)] = 0.5f;
  const std::vector<uint32_t> divided = clearRegions(GridCells(e), d.data(), kSegment);
  EXPECT_EQ(divided[e.index(11, 3, 3)], e.index(7, 0, 0));
  EXPECT_EQ(divided[e.index(4, 3, 3)], 0u);
  EXPECT_EQ(divided[e.index(6, 2, 1)], e.index(6, 2, 1));  // certified to no neighbour: alone
}

}  // namespace
}  // namespace lbmshape
