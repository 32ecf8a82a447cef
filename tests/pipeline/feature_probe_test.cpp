// The copy --preserve-features finds the edges on: how it is smoothed.
#include <gtest/gtest.h>

#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/lbm/reference_solver.hpp"
#include "lbmshape/pipeline/feature_probe.hpp"

namespace lbmshape {
namespace {

TEST(FeatureProbe, ReachesTheVarianceInTheFewestSteps)
{
  const FeatureProbe probe = featureProbe();
  EXPECT_NEAR(spreadVariance(probe.gamma, probe.steps), featureProbeVariance, 1e-9);
  EXPECT_GT(probe.gamma, 0.0);
  EXPECT_LE(probe.gamma, parameter_bounds::maxGamma);
  EXPECT_LT(spreadVariance(parameter_bounds::maxGamma, probe.steps - 1), featureProbeVariance)
      << "one step fewer reaches it at no gamma allowed";
  EXPECT_LT(probe.steps, 10) << "fewer than the 10 steps of 0.2 it took before";
}

// spreadVariance is what the lattice does: a point pulse on the CPU
// reference spreads to it after the probe's steps.
TEST(FeatureProbe, TheLatticeSpreadsAPulseToThatVariance)
{
  const FeatureProbe probe = featureProbe();
  const Extent3 extent{33, 33, 33};
  Volume pulse(extent);
  pulse.at(16, 16, 16) = 1.0f;
  ReferenceSolver solver(extent);
  solver.setUniformGamma(probe.gamma);
  solver.initialize(pulse);
  solver.step(probe.steps);
  const Volume spread = solver.field();
  double mass = 0.0, second = 0.0;
  for (int z = 0; z < extent.nz; ++z)
    for (int y = 0; y < extent.ny; ++y)
      for (int x = 0; x < extent.nx; ++x) {
        const double v = spread.at(x, y, z);
        mass += v;
        second += v * double((x - 16) * (x - 16));
      }
  EXPECT_NEAR(mass, 1.0, 1e-4);
  EXPECT_NEAR(second / mass, featureProbeVariance, 0.02 * featureProbeVariance) << "the variance along x";
}

}  // namespace
}  // namespace lbmshape
