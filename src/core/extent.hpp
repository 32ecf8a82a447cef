// Grid dimensions and linear indexing of a regular 3D grid (x fastest).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace lbmshape {

struct Extent3 {
  int nx = 0, ny = 0, nz = 0;

  size_t cells() const { return size_t(nx) * size_t(ny) * size_t(nz); }
  size_t index(int x, int y, int z) const { return size_t(x) + size_t(nx) * (size_t(y) + size_t(ny) * size_t(z)); }
  // The cell (x, y, z) of a linear index, index()'s inverse.
  std::array<int, 3> cellAt(size_t i) const
  {
    return {int(i % size_t(nx)), int(i / size_t(nx) % size_t(ny)), int(i / size_t(nx) / size_t(ny))};
  }
  bool contains(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x < nx && y < ny && z < nz; }
  bool operator==(const Extent3&) const = default;
  std::string toString() const { return std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz); }
};

}  // namespace lbmshape
