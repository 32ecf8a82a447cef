// Narrow-band fields for the tests, made from whole-grid ones: which bricks
// to keep, the band's values of a grid field and back, and band solvers on
// either back end.
#pragma once

#include <memory>

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/core/volume.hpp"
#include "lbmshape/lbm/band_solver.hpp"
#include "support/backends.hpp"

namespace lbmshape::testing {

// The bricks with a cell where |X| < reach (all bricks for an infinite reach).
std::shared_ptr<BrickSet> bricksNear(const Volume& field, double reach);
// The band's values of a grid field; inactive bricks take the side of X at
// their first cell.
BandField bandOf(const Volume& field, std::shared_ptr<const BrickSet> bricks);
// Value of a band field at each stored cell; NaN elsewhere.
Volume gridOf(const BandField& band);

std::unique_ptr<BandSolver> makeBandSolver(Backend backend, std::shared_ptr<const BrickSet> bricks);

// max |band - grid| over the stored cells of the band where `where` holds.
double maxDifference(const BandField& band, const Volume& grid, const std::function<bool(float gridValue)>& where);

// max |got - expected| over the stored cells inside `extent`, and the
// largest |expected| there: a device's band field against the reference's,
// whose tolerance scales with the field's magnitude.
struct BandDifference {
  double worst = 0.0;
  double scale = 0.0;
};
BandDifference differenceInside(const BandField& got, const BandField& expected, Extent3 extent);

}  // namespace lbmshape::testing
