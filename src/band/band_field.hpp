// A scalar field on the narrow band: one float per cell of every active
// brick (the sparse counterpart of Volume). Cells of inactive bricks are not
// stored: they are far from the surface, and read as +farValue inside the
// surface and -farValue outside, by the side their brick was found on when
// the band was made.
#pragma once

#include <memory>
#include <vector>

#include "lbmshape/band/brick_set.hpp"

namespace lbmshape {

class BandField {
public:
  BandField() = default;
  BandField(std::shared_ptr<const BrickSet> bricks, float farValue);

  const BrickSet& bricks() const { return *bricks_; }
  const std::shared_ptr<const BrickSet>& sharedBricks() const { return bricks_; }
  const Extent3& extent() const { return bricks_->cells(); }
  // A field on the same bricks with the same far value and sides, its
  // stored values 0: what a solver fills with the values it computes.
  BandField sameShape() const
  {
    BandField out(bricks_, farValue_);
    out.farSide_ = farSide_;
    return out;
  }
  float farValue() const { return farValue_; }

  // Stored values, slot * brickCells + cellInBrick; cells beyond the grid
  // (in bricks at its far faces) hold farValue with the brick's side.
  std::vector<float>& values() { return values_; }
  const std::vector<float>& values() const { return values_; }

  // +1 when the cells of inactive brick (bx, by, bz) are inside, -1 outside.
  int8_t farSide(int bx, int by, int bz) const { return farSide_[bricks_->bricks().index(bx, by, bz)]; }
  std::vector<int8_t>& farSides() { return farSide_; }  // per brick of the brick grid
  const std::vector<int8_t>& farSides() const { return farSide_; }

  // The value at cell (x, y, z) of the grid, stored or not.
  float at(int x, int y, int z) const
  {
    const int64_t i = bricks_->storedIndex(x, y, z);
    if (i >= 0) return values_[size_t(i)];
    return farValue_ * farSide(BrickSet::floorDiv(x), BrickSet::floorDiv(y), BrickSet::floorDiv(z));
  }

private:
  std::shared_ptr<const BrickSet> bricks_;
  float farValue_ = 0.0f;
  std::vector<float> values_;
  std::vector<int8_t> farSide_;
};

}  // namespace lbmshape
