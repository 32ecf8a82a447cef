// How far the surface moved in a step, less what a level-set shift undoes,
// on the host (lbm/surface_change.hpp).
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "lbmshape/lbm/surface_change.hpp"

namespace lbmshape {
namespace {

TEST(SurfaceChange, IsTheStandardDeviationOverTheCellsTheSurfacePassedThrough)
{
  // Cells 0, 1 and 3 were within a voxel of the surface (changes -0.25,
  // +0.5, +0.75); 2 and 4 were not, whatever they did.
  const std::vector<float> before = {0.5f, -0.75f, 3.0f, 0.0f, -1.0f};
  const std::vector<float> after = {0.25f, -0.25f, -7.0f, 0.75f, 5.0f};
  const double mean = (-0.25 + 0.5 + 0.75) / 3.0;
  const double variance =
      ((-0.25 - mean) * (-0.25 - mean) + (0.5 - mean) * (0.5 - mean) + (0.75 - mean) * (0.75 - mean)) / 3.0;
  EXPECT_NEAR(surfaceSpeed(after, before), std::sqrt(variance), 1e-12);
}

// A surface that moves everywhere by the same amount (a sphere or a tube
// shrinking under its own curvature) has nothing left once keeping the
// volume shifts it back: no speed. Any unevenness is speed.
TEST(SurfaceChange, AUniformMoveHasNoSpeed)
{
  const std::vector<float> before = {0.5f, -0.25f, 0.0f, 0.75f};
  std::vector<float> after = before;
  for (float& x : after) x += 0.125f;
  EXPECT_NEAR(surfaceSpeed(after, before), 0.0, 1e-9);
  after[0] += 0.5f;
  EXPECT_GT(surfaceSpeed(after, before), 0.2);
}

TEST(SurfaceChange, NoSurfaceNoSpeedAndSizesMustAgree)
{
  EXPECT_EQ(surfaceSpeed({1.0f, 2.0f}, {5.0f, -5.0f}), 0.0);
  EXPECT_THROW(surfaceSpeed({1.0f}, {1.0f, 2.0f}), std::invalid_argument);
}

TEST(SurfaceChange, SumsAddUpAsOneSum)
{
  SurfaceChangeSums whole, first, second;
  const float before[] = {0.5f, -0.25f, 0.0f, 0.75f}, after[] = {0.0f, 0.25f, 0.5f, 0.5f};
  for (int i = 0; i < 4; ++i) whole.add(before[i], after[i]);
  for (int i = 0; i < 2; ++i) first.add(before[i], after[i]);
  for (int i = 2; i < 4; ++i) second.add(before[i], after[i]);
  first += second;
  EXPECT_DOUBLE_EQ(first.speed(), whole.speed());
  EXPECT_EQ(first.cells, 4.0);
}

}  // namespace
}  // namespace lbmshape
