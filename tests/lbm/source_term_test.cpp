// The source term: a constant S adds exactly S per step to every cell,
// walls included, whatever gamma is; and the morph force S = Cs (T - X) relaxes
// a uniform field towards T as the ODE dX/dt = Cs (T - X) does.
#include <cmath>

#include <gtest/gtest.h>

#include "support/backends.hpp"
#include "support/fields.hpp"

namespace lbmshape {
namespace {

class SourceTerm : public testing::BackendTest {};

TEST_P(SourceTerm, ConstantSourceAddsSPerStepEverywhere)
{
  const Extent3 extent{17, 12, 9};
  const float S = 0.125f;
  for (double gamma : {0.01, 0.2, 1.0}) {  // 1: the largest accepted (core/parameter_bounds.hpp)
    auto solver = this->solver(extent);
    solver->setUniformGamma(gamma);
    solver->setSource(LinearSource{Volume(extent, S), 0.0f});
    Volume initial = testing::randomField(extent, -1.0f, 1.0f, 21);
    solver->initialize(initial);
    Volume before = solver->field();
    EXPECT_LT(testing::maxRelativeDifference(before, initial, 1.0), 1e-6) << "initialize must report the given field";
    Volume diffused = before;
    for (int steps = 1; steps <= 3; ++steps) {
      // Diffusion alone conserves the total, so the source must add exactly
      // S per cell per step to the sum, and (for a uniform S) to every cell
      // relative to the same lattice without a source.
      solver->step(1);
      Volume after = solver->field();
      EXPECT_NEAR(testing::sum(after) - testing::sum(initial), double(S) * steps * extent.cells(), 1e-3)
          << "gamma " << gamma;
    }
    auto plain = this->solver(extent);
    plain->setUniformGamma(gamma);
    plain->initialize(initial);
    plain->step(3);
    Volume without = plain->field();
    Volume with = solver->field();
    for (size_t i = 0; i < with.size(); ++i) ASSERT_NEAR(with[i] - without[i], 3 * S, 2e-6) << "cell " << i;
  }
}

TEST_P(SourceTerm, MorphForceRelaxesTowardsTarget)
{
  // Uniform start and target: no diffusion, only dX/dt = c (T - X). The
  // second-order scheme is the trapezoidal rule: e = e0 ((1 - c/2)/(1 + c/2))^n.
  const Extent3 extent{9, 8, 7};
  const float c = 0.1f, target = 2.0f, start = -1.0f;
  auto solver = this->solver(extent);
  solver->setUniformGamma(0.05);
  solver->setSource(LinearSource{Volume(extent, c * target), c});
  solver->initialize(Volume(extent, start));
  solver->step(20);
  const double expected = target + (start - target) * std::pow((1.0 - c / 2) / (1.0 + c / 2), 20);
  Volume X = solver->field();
  for (size_t i = 0; i < X.size(); ++i) ASSERT_NEAR(X[i], expected, 1e-5);
  EXPECT_NEAR(expected, target + (start - target) * std::exp(-c * 20), 2e-3) << "close to the exact ODE solution";
}

// A morph's closing changes Cs at every step: setSourceStrength(c, c) on
// the target itself must act as a new source c T - c X would, without the
// upload; and after it the trapezoidal rule with the new c holds.
TEST_P(SourceTerm, ChangingTheStrengthActsAsANewScaledSource)
{
  const Extent3 extent{13, 11, 9};
  const Volume target = testing::randomField(extent, -2.0f, 2.0f, 5);
  const Volume start = testing::randomField(extent, -1.0f, 1.0f, 6);
  auto scaled = [&](float c) {
    Volume v = target;
    for (float& x : v.values()) x *= c;
    return LinearSource{std::move(v), c};
  };
  auto strength = this->solver(extent), uploads = this->solver(extent);
  strength->setUniformGamma(0.05);
  uploads->setUniformGamma(0.05);
  strength->setSource(LinearSource{target, 0.1f, 0.1f});
  uploads->setSource(scaled(0.1f));
  strength->initialize(start);
  uploads->initialize(start);
  for (float c : {0.1f, 0.3f, 0.6f, 1.0f}) {
    strength->setSourceStrength(c, c);
    uploads->setSource(scaled(c));
    strength->step(2);
    uploads->step(2);
  }
  const Volume a = strength->field(), b = uploads->field();
  EXPECT_LT(testing::maxDifferenceForItsScale(a, b), testing::deviceTolerance);
  EXPECT_GT(testing::maxDifferenceForItsScale(a, start), 0.1) << "the source moved the field";
}

TEST_P(SourceTerm, AStrengthNeedsASource)
{
  auto solver = this->solver(Extent3{4, 4, 4});
  EXPECT_THROW(solver->setSourceStrength(0.1f, 0.1f), std::logic_error);
}

LBMSHAPE_ON_BOTH_BACKENDS(SourceTerm);

}  // namespace
}  // namespace lbmshape
