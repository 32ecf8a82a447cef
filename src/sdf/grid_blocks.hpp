// A grid cut into cubes of `size` cells (smaller at the far faces), the unit
// of work that the distance and sign stages prune and hand to threads.
#pragma once

#include <algorithm>
#include <cstddef>

#include "lbmshape/core/extent.hpp"

namespace lbmshape {

struct CellRange {
  int x0, y0, z0;  // first cell
  int x1, y1, z1;  // one past the last
};

class GridBlocks {
public:
  GridBlocks(Extent3 extent, int size)
      : size_(size), nx_((extent.nx + size - 1) / size), ny_((extent.ny + size - 1) / size),
        nz_((extent.nz + size - 1) / size), extent_(extent)
  {}

  size_t count() const { return size_t(nx_) * ny_ * nz_; }
  int size() const { return size_; }

  CellRange range(size_t block) const
  {
    const int bx = int(block % nx_), by = int(block / nx_ % ny_), bz = int(block / nx_ / ny_);
    return {bx * size_,
            by * size_,
            bz * size_,
            std::min(bx * size_ + size_, extent_.nx),
            std::min(by * size_ + size_, extent_.ny),
            std::min(bz * size_ + size_, extent_.nz)};
  }

  size_t blockOf(int x, int y, int z) const
  {
    return size_t(x / size_) + size_t(nx_) * (y / size_ + size_t(ny_) * (z / size_));
  }

private:
  int size_, nx_, ny_, nz_;
  Extent3 extent_;
};

}  // namespace lbmshape
