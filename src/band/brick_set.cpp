#include "lbmshape/band/brick_set.hpp"

namespace lbmshape {

BrickSet::BrickSet(Extent3 cells)
    : cells_(cells), bricks_{(cells.nx + brickEdge - 1) / brickEdge, (cells.ny + brickEdge - 1) / brickEdge,
                             (cells.nz + brickEdge - 1) / brickEdge},
      table_(bricks_.cells(), noBrick)
{}

int32_t BrickSet::activate(int bx, int by, int bz)
{
  int32_t& entry = table_[bricks_.index(bx, by, bz)];
  if (entry == noBrick) {
    entry = int32_t(coordinates_.size());
    coordinates_.emplace_back(bx, by, bz);
  }
  return entry;
}

std::vector<glm::ivec4> BrickSet::originTable() const
{
  std::vector<glm::ivec4> table(activeCount());
  for (size_t s = 0; s < activeCount(); ++s) table[s] = glm::ivec4(brickEdge * coordinates_[s], 0);
  return table;
}

std::vector<int32_t> BrickSet::neighbourTable() const
{
  std::vector<int32_t> table(activeCount() * 27);
  for (size_t s = 0; s < activeCount(); ++s) {
    const glm::ivec3 b = coordinates_[s];
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          table[s * 27 + size_t((dx + 1) + 3 * (dy + 1) + 9 * (dz + 1))] = slot(b.x + dx, b.y + dy, b.z + dz);
  }
  return table;
}

}  // namespace lbmshape
