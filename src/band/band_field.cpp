#include "lbmshape/band/band_field.hpp"

namespace lbmshape {

BandField::BandField(std::shared_ptr<const BrickSet> bricks, float farValue)
    : bricks_(std::move(bricks)), farValue_(farValue), values_(bricks_->storedCells(), 0.0f),
      farSide_(bricks_->bricks().cells(), int8_t(-1))
{}

}  // namespace lbmshape
