// The cells a stage of the signed distance works on, with their neighbours
// and their division into blocks of work: every cell of a grid
// (GridCells), or the cells of the narrow band's active bricks (BandCells).
// The sign stage is written once against this interface and runs on both.
//
// A cell is a number in [0, count()); real() is false for the cells of the
// band's bricks that lie beyond the grid, which stages skip.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/band/brick_set.hpp"
#include "lbmshape/core/extent.hpp"
#include "lbmshape/sdf/grid_blocks.hpp"

namespace lbmshape {

inline constexpr size_t noCell = std::numeric_limits<size_t>::max();

// The 26 offsets of a cell's neighbourhood.
inline const std::array<glm::ivec3, 26>& neighbourSteps()
{
  static const std::array<glm::ivec3, 26> steps = [] {
    std::array<glm::ivec3, 26> s{};
    int k = 0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (dx || dy || dz) s[size_t(k++)] = {dx, dy, dz};
    return s;
  }();
  return steps;
}

class GridCells {
public:
  explicit GridCells(Extent3 extent, int blockSize = 4) : e_(extent), blocks_(extent, blockSize)
  {
    for (size_t k = 0; k < 26; ++k) {
      const glm::ivec3 d = neighbourSteps()[k];
      offsets_[k] = (ptrdiff_t(d.z) * e_.ny + d.y) * e_.nx + d.x;
    }
  }

  size_t count() const { return e_.cells(); }
  bool real(size_t) const { return true; }
  glm::ivec3 coords(size_t i) const { return {int(i % e_.nx), int(i / e_.nx % e_.ny), int(i / e_.nx / e_.ny)}; }
  // The cell at c + d (c the coordinates of cell i), or noCell beyond the grid.
  size_t neighbour(size_t i, const glm::ivec3& c, const glm::ivec3& d) const
  {
    const glm::ivec3 n = c + d;
    if (!e_.contains(n.x, n.y, n.z)) return noCell;
    return size_t(ptrdiff_t(i) + (ptrdiff_t(d.z) * e_.ny + d.y) * e_.nx + d.x);
  }

  // f(neighbour index) for the six face neighbours of cell i (coordinates
  // c) inside the grid, in the order -x, +x, -y, +y, -z, +z.
  template <class F>
  void forEachFaceNeighbour(size_t i, const glm::ivec3& c, F&& f) const
  {
    const ptrdiff_t row = e_.nx, plane = ptrdiff_t(e_.nx) * e_.ny;
    if (c.x > 0) f(i - 1);
    if (c.x < e_.nx - 1) f(i + 1);
    if (c.y > 0) f(size_t(ptrdiff_t(i) - row));
    if (c.y < e_.ny - 1) f(size_t(ptrdiff_t(i) + row));
    if (c.z > 0) f(size_t(ptrdiff_t(i) - plane));
    if (c.z < e_.nz - 1) f(size_t(ptrdiff_t(i) + plane));
  }

  // f(neighbour index, its coordinates) for the 26 neighbours of cell i
  // (coordinates c) inside the grid; bounds are checked only on the faces.
  template <class F>
  void forEachNeighbour(size_t i, const glm::ivec3& c, F&& f) const
  {
    const bool inside = c.x > 0 && c.y > 0 && c.z > 0 && c.x < e_.nx - 1 && c.y < e_.ny - 1 && c.z < e_.nz - 1;
    for (size_t k = 0; k < 26; ++k) {
      const glm::ivec3 n = c + neighbourSteps()[k];
      if (inside || e_.contains(n.x, n.y, n.z)) f(size_t(ptrdiff_t(i) + offsets_[k]), n);
    }
  }

  size_t blockCount() const { return blocks_.count(); }
  size_t blockOf(size_t i) const
  {
    const glm::ivec3 c = coords(i);
    return blocks_.blockOf(c.x, c.y, c.z);
  }
  // First and one-past-last cell of block b.
  void blockRange(size_t b, glm::ivec3& lo, glm::ivec3& hi) const
  {
    const CellRange r = blocks_.range(b);
    lo = {r.x0, r.y0, r.z0};
    hi = {r.x1, r.y1, r.z1};
  }
  template <class F>
  void forEachCellOf(size_t b, F&& f) const
  {
    const CellRange r = blocks_.range(b);
    for (int z = r.z0; z < r.z1; ++z)
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) f(e_.index(x, y, z), glm::ivec3(x, y, z));
  }

private:
  Extent3 e_;
  GridBlocks blocks_;
  std::array<ptrdiff_t, 26> offsets_{};
};

class BandCells {
public:
  explicit BandCells(const BrickSet& bricks) : bricks_(bricks), neighbours_(bricks.neighbourTable()) {}

  const BrickSet& bricks() const { return bricks_; }

  size_t count() const { return bricks_.storedCells(); }
  glm::ivec3 coords(size_t i) const { return bricks_.cell(int32_t(i / brickCells), int(i % brickCells)); }
  bool real(size_t i) const
  {
    const glm::ivec3 c = coords(i);
    return bricks_.cells().contains(c.x, c.y, c.z);
  }
  size_t neighbour(size_t i, const glm::ivec3& c, const glm::ivec3& d) const
  {
    const glm::ivec3 n = c + d;
    if (!bricks_.cells().contains(n.x, n.y, n.z)) return noCell;
    const glm::ivec3 local = c & (brickEdge - 1);
    const glm::ivec3 shifted = local + d;
    // Which neighbouring brick: -1, 0 or 1 along each axis.
    const glm::ivec3 step = glm::ivec3(shifted.x >> 3, shifted.y >> 3, shifted.z >> 3);
    const int32_t slot = neighbours_[i / brickCells * 27 + size_t((step.x + 1) + 3 * (step.y + 1) + 9 * (step.z + 1))];
    if (slot == noBrick) return noCell;
    const glm::ivec3 inside = shifted & (brickEdge - 1);
    return size_t(slot) * brickCells + size_t(cellInBrick(inside.x, inside.y, inside.z));
  }

  // f(neighbour index) for the six face neighbours of cell i that are
  // stored cells inside the grid, in the order -x, +x, -y, +y, -z, +z;
  // within a brick that the grid holds, without the brick table.
  template <class F>
  void forEachFaceNeighbour(size_t i, const glm::ivec3& c, F&& f) const
  {
    const glm::ivec3 local = c & (brickEdge - 1);
    const Extent3& e = bricks_.cells();
    if (glm::all(glm::greaterThan(local, glm::ivec3(0))) && glm::all(glm::lessThan(local, glm::ivec3(brickEdge - 1))) &&
        c.x + 1 < e.nx && c.y + 1 < e.ny && c.z + 1 < e.nz) {
      constexpr size_t row = brickEdge, plane = brickEdge * brickEdge;
      f(i - 1), f(i + 1), f(i - row), f(i + row), f(i - plane), f(i + plane);
      return;
    }
    for (int axis = 0; axis < 3; ++axis)
      for (int s = -1; s <= 1; s += 2) {
        glm::ivec3 d(0);
        d[axis] = s;
        const size_t j = neighbour(i, c, d);
        if (j != noCell) f(j);
      }
  }

  // f(neighbour index, its coordinates) for the 26 neighbours of cell i
  // that are stored cells inside the grid.
  template <class F>
  void forEachNeighbour(size_t i, const glm::ivec3& c, F&& f) const
  {
    const glm::ivec3 local = c & (brickEdge - 1);
    const bool inside =
        glm::all(glm::greaterThan(local, glm::ivec3(0))) && glm::all(glm::lessThan(local, glm::ivec3(brickEdge - 1)));
    for (const glm::ivec3& d : neighbourSteps()) {
      if (inside) {
        f(size_t(ptrdiff_t(i) + d.x + brickEdge * (d.y + brickEdge * d.z)), c + d);
        continue;
      }
      const size_t j = neighbour(i, c, d);
      if (j != noCell) f(j, c + d);
    }
  }

  size_t blockCount() const { return bricks_.activeCount(); }
  size_t blockOf(size_t i) const { return i / brickCells; }
  void blockRange(size_t b, glm::ivec3& lo, glm::ivec3& hi) const
  {
    lo = brickEdge * bricks_.brick(int32_t(b));
    hi = glm::min(lo + brickEdge, glm::ivec3(bricks_.cells().nx, bricks_.cells().ny, bricks_.cells().nz));
  }
  template <class F>
  void forEachCellOf(size_t b, F&& f) const
  {
    for (int local = 0; local < brickCells; ++local) {
      const size_t i = b * brickCells + size_t(local);
      const glm::ivec3 c = coords(i);
      if (bricks_.cells().contains(c.x, c.y, c.z)) f(i, c);
    }
  }

private:
  const BrickSet& bricks_;
  std::vector<int32_t> neighbours_;
};

}  // namespace lbmshape
