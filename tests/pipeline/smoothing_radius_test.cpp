// --radius (pipeline/smoothing_radius.hpp): a smoothing strength in the
// mesh's units, the same at any resolution.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/pipeline/feature_probe.hpp"
#include "lbmshape/pipeline/smoothing_radius.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

TEST(SmoothingRadius, StepsAreTheFewestThatReachTheVariance)
{
  for (double gamma : {0.05, 0.2, 0.5})
    for (double radius : {0.3, 1.0, 2.5, 7.0, 30.0}) {
      const int steps = stepsForRadius(radius, gamma);
      EXPECT_GE(spreadVariance(gamma, steps), radius * radius) << gamma << ", " << radius;
      if (steps > 1) {
        EXPECT_LT(spreadVariance(gamma, steps - 1), radius * radius) << gamma << ", " << radius;
      }
    }
  EXPECT_EQ(stepsForRadius(1e-6, 0.2), 1);
  EXPECT_THROW(stepsForRadius(1e9, 0.2), UsageError);
}

// Two radii of margin, counted in the voxels of the grid that margin makes.
TEST(SmoothingRadius, TheMarginHoldsTwoRadii)
{
  const double longest = 2.0;
  for (int resolution : {48, 128, 400})
    for (double radius : {0.01, 0.1, 0.3}) {
      const double margin = marginForRadius(radius, longest, resolution, std::nullopt);
      const auto voxelWith = [&](double m) { return longest / (resolution - 1.0 - 2.0 * m); };
      EXPECT_GE(margin * voxelWith(margin), 2.0 * radius - 1e-12) << resolution << ", " << radius;
      if (margin > 0) {
        EXPECT_LT((margin - 1.0) * voxelWith(margin - 1.0), 2.0 * radius) << "the fewest: " << resolution;
      }
    }
  EXPECT_EQ(marginForRadius(0.25, longest, 48, 0.1), 5.0) << "a given voxel: 2 radii / voxel, rounded up";
  EXPECT_THROW(marginForRadius(100.0, longest, 48, std::nullopt), UsageError) << "no cells left for the mesh";
  EXPECT_NO_THROW(checkRadius(std::nullopt, true));
  EXPECT_THROW(checkRadius(0.1, true), UsageError) << "and --steps";
  for (double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(checkRadius(bad, false), UsageError) << bad;
}

// The heat equation moves a sphere's distance field X = rho - r exactly:
// -2/r is harmonic, so X(t) = rho - r - 2 gamma t / r, whose zero level is
// r = (rho + sqrt(rho^2 - 4 s^2)) / 2 with s^2 = 2 gamma t the variance in
// world units. With --radius s the unit sphere shrinks there at any grid,
// within a tenth of the coarser voxel; the steps of the coarser grid run on
// the finer one smooth a quarter as much, and miss it.
TEST(SmoothingRadius, ASphereShrinksAsTheHeatEquationSaysAtAnyResolution)
{
  const ComputeDevice device{"", true};
  const TriangleMesh sphere = testing::icosphere(5);
  const double s = 0.2, expected = (1.0 + std::sqrt(1.0 - 4.0 * s * s)) / 2.0;
  const auto meanRadius = [](const TriangleMesh& mesh) {
    double sum = 0.0;
    for (const glm::dvec3& p : mesh.positions) sum += glm::length(p);
    return sum / double(mesh.positions.size());
  };
  DenoiseOptions options;
  options.smoothing = Smoothing::Isotropic;
  options.keepVolume = false;
  options.radius = s;
  options.grid.resolution = 40;
  const DenoiseResult coarse = denoiseMesh(sphere, "sphere", options, device);
  options.grid.resolution = 80;
  const DenoiseResult fine = denoiseMesh(sphere, "sphere", options, device);
  const double coarseVoxel = coarse.report["grid"]["voxel"];
  EXPECT_NEAR(meanRadius(coarse.mesh), expected, 0.1 * coarseVoxel);
  EXPECT_NEAR(meanRadius(fine.mesh), expected, 0.1 * coarseVoxel);
  const int coarseSteps = coarse.report["steps"], fineSteps = fine.report["steps"];
  EXPECT_GT(fineSteps, 3 * coarseSteps);
  options.radius.reset();
  options.steps = coarseSteps;
  const DenoiseResult sameSteps = denoiseMesh(sphere, "sphere", options, device);
  EXPECT_GT(meanRadius(sameSteps.mesh) - expected, 0.25 * coarseVoxel);
}

}  // namespace
}  // namespace lbmshape
