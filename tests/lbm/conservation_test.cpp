// Without a source, streaming with bounce-back walls and a collision that
// keeps sum_i f_i conserve the total of X exactly (up to fp32 rounding).
#include <gtest/gtest.h>

#include "support/backends.hpp"
#include "support/fields.hpp"

namespace lbmshape {
namespace {

class Conservation : public testing::BackendTest {};

TEST_P(Conservation, TotalFieldIsConstantOver1000Steps)
{
  const Extent3 extent{24, 19, 17};
  auto solver = this->solver(extent);
  solver->setUniformGamma(0.3);
  Volume initial = testing::randomField(extent, 0.0f, 2.0f, 5);
  solver->initialize(initial);
  const double before = testing::sum(initial);
  solver->step(1000);
  Volume after = solver->field();
  EXPECT_NEAR(testing::sum(after) / before, 1.0, 1e-5);
  // After 1000 steps the random field has diffused almost flat: the walls were
  // really hit, many times, and still nothing leaked.
  EXPECT_LT(testing::maxRelativeDifference(after, Volume(extent, float(before / extent.cells()))), 0.05);
}

TEST_P(Conservation, PerCellRelaxationAlsoConserves)
{
  const Extent3 extent{13, 21, 8};
  auto solver = this->solver(extent);
  solver->setGammaPerCell(testing::randomField(extent, 0.01f, 1.0f, 9));
  Volume initial = testing::randomField(extent, 0.0f, 2.0f, 6);
  solver->initialize(initial);
  solver->step(1000);
  EXPECT_NEAR(testing::sum(solver->field()) / testing::sum(initial), 1.0, 1e-5);
}

LBMSHAPE_ON_BOTH_BACKENDS(Conservation);

}  // namespace
}  // namespace lbmshape
