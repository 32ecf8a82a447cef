// The narrow band's bricks: the grid cut into cubes of 8 x 8 x 8 cells, of
// which only those near the surface are stored ("active"), each in a slot of
// its own. The sparse counterpart of Extent3: the signed distance field, the
// lattice and marching cubes all address cells as (slot, cell within brick).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/core/extent.hpp"

namespace lbmshape {

inline constexpr int brickEdge = 8;
inline constexpr int brickCells = brickEdge * brickEdge * brickEdge;
inline constexpr int32_t noBrick = -1;

// Cell (x, y, z) of a brick, x fastest.
constexpr int cellInBrick(int x, int y, int z) { return x + brickEdge * (y + brickEdge * z); }

class BrickSet {
public:
  BrickSet() = default;
  // A set with no active brick over a grid of `cells`; bricks at the far
  // faces reach beyond the grid when a side is not a multiple of 8.
  explicit BrickSet(Extent3 cells);

  const Extent3& cells() const { return cells_; }
  const Extent3& bricks() const { return bricks_; }  // the brick grid
  size_t activeCount() const { return coordinates_.size(); }
  // Cells that active bricks hold (padding beyond the grid included).
  size_t storedCells() const { return activeCount() * brickCells; }

  // The slot of brick (bx, by, bz), or noBrick when it is inactive or
  // outside the brick grid.
  int32_t slot(int bx, int by, int bz) const
  {
    if (!bricks_.contains(bx, by, bz)) return noBrick;
    return table_[bricks_.index(bx, by, bz)];
  }
  // The slot of the brick holding cell (x, y, z) of the grid.
  int32_t slotOfCell(int x, int y, int z) const { return slot(floorDiv(x), floorDiv(y), floorDiv(z)); }
  // Makes the brick active (if it is not) and returns its slot. Slots are
  // given in the order of activation. Not thread-safe.
  int32_t activate(int bx, int by, int bz);

  glm::ivec3 brick(int32_t slot) const { return coordinates_[size_t(slot)]; }
  // Grid coordinates of cell `local` (cellInBrick) of a slot's brick.
  glm::ivec3 cell(int32_t slot, int local) const
  {
    return brickEdge * coordinates_[size_t(slot)] +
           glm::ivec3(local % brickEdge, local / brickEdge % brickEdge, local / (brickEdge * brickEdge));
  }
  // Index of a stored cell: slot * brickCells + cell within brick; -1 when
  // the cell's brick is not active (or the cell is outside the grid).
  int64_t storedIndex(int x, int y, int z) const
  {
    if (!cells_.contains(x, y, z)) return -1;
    const int32_t s = slotOfCell(x, y, z);
    return s == noBrick ? -1 : int64_t(s) * brickCells + cellInBrick(x & 7, y & 7, z & 7);
  }

  // For every slot, the slots of its 27 neighbours (itself in the middle),
  // index (dx + 1) + 3 (dy + 1) + 9 (dz + 1); noBrick where there is none.
  std::vector<int32_t> neighbourTable() const;
  // For every slot, its brick's first cell in the grid (w 0): the origins
  // table the band's shaders read (band_interface.h, band_distance_interface.h).
  std::vector<glm::ivec4> originTable() const;

  static int floorDiv(int c) { return c >= 0 ? c / brickEdge : -((-c + brickEdge - 1) / brickEdge); }

private:
  Extent3 cells_, bricks_;
  std::vector<int32_t> table_;           // per brick of the brick grid
  std::vector<glm::ivec3> coordinates_;  // per slot
};

}  // namespace lbmshape
