// How far the surface moved in a step, on the host (lbm/surface_change.hpp).
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "lbm/surface_change.hpp"

namespace lbmshape {
namespace {

TEST(SurfaceChange, AveragesOverTheCellsTheSurfacePassedThrough)
{
  // Cells 0, 1 and 3 were within a voxel of the surface; 2 and 4 were not,
  // whatever they did.
  const std::vector<float> before = {0.5f, -0.75f, 3.0f, 0.0f, -1.0f};
  const std::vector<float> after = {0.25f, -0.25f, -7.0f, 0.75f, 5.0f};
  EXPECT_DOUBLE_EQ(meanSurfaceChange(after, before), (0.25 + 0.5 + 0.75) / 3.0);
}

TEST(SurfaceChange, NoSurfaceNoSpeedAndSizesMustAgree)
{
  EXPECT_EQ(meanSurfaceChange({1.0f, 2.0f}, {5.0f, -5.0f}), 0.0);
  EXPECT_THROW(meanSurfaceChange({1.0f}, {1.0f, 2.0f}), std::invalid_argument);
}

}  // namespace
}  // namespace lbmshape
