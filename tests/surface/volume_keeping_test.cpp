// The level-set shift that keeps a denoise's volume (surface/volume_keeping):
// the ramp count of enclosed voxels, and the shift that restores a count.
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "surface/volume_keeping.hpp"
#include "support/band_fields.hpp"
#include "support/fields.hpp"

namespace lbmshape {
namespace {

const Extent3 extent{40, 37, 43};
const glm::dvec3 centre(19.3, 18.1, 21.7);  // off the cell centres

Volume sphere(double radius) { return testing::sphereDistance(extent, centre.x, centre.y, centre.z, radius); }

TEST(VolumeKeeping, CountsASpheresVolumeInVoxels)
{
  // The ramp is exact for a plane; on a sphere its error falls with the
  // curvature squared (measured: +0.71 % at a radius of 6 voxels).
  for (double radius : {6.0, 11.5, 15.2}) {
    const double exact = 4.0 / 3.0 * glm::pi<double>() * radius * radius * radius;
    EXPECT_NEAR(enclosedVoxels(sphere(radius)), exact, 0.3 / (radius * radius) * exact) << "radius " << radius;
  }
}

TEST(VolumeKeeping, TheShiftGrowsAShrunkSphereBack)
{
  // A sphere of 12 voxels that lost 0.37 voxel all round, as smoothing
  // would shrink it: the shift that restores the count is 0.37.
  const double enclosed = enclosedVoxels(sphere(12.0));
  Volume shrunk = sphere(12.0 - 0.37);
  const double d = volumeKeepingShift(shrunk, enclosed, 2.0);
  EXPECT_NEAR(d, 0.37, 0.01);
  shiftField(shrunk, d);
  EXPECT_NEAR(enclosedVoxels(shrunk), enclosed, 1e-6 * enclosed);
  // And a grown one shrinks back.
  EXPECT_NEAR(volumeKeepingShift(sphere(12.6), enclosed, 2.0), -0.6, 0.01);
}

TEST(VolumeKeeping, TheShiftIsBounded)
{
  const double enclosed = enclosedVoxels(sphere(12.0));
  EXPECT_EQ(volumeKeepingShift(sphere(8.0), enclosed, 2.0), 2.0);
  EXPECT_EQ(volumeKeepingShift(sphere(16.0), enclosed, 1.5), -1.5);
}

TEST(VolumeKeeping, TheBandGivesTheGridsShift)
{
  const Volume grid = sphere(12.0 - 0.37);
  auto bricks = testing::bricksNear(grid, 6.0);
  BandField band = testing::bandOf(grid, bricks);
  // On the band only the stored cells are counted (the far ones are the same
  // before and after), so the target is the band's own count.
  const double enclosed = enclosedVoxels(testing::bandOf(sphere(12.0), bricks));
  const double d = volumeKeepingShift(band, enclosed, 2.0);
  EXPECT_NEAR(d, volumeKeepingShift(grid, enclosedVoxels(sphere(12.0)), 2.0), 1e-3);
  shiftField(band, d);
  EXPECT_NEAR(enclosedVoxels(band), enclosed, 1e-6 * enclosed);
}

}  // namespace
}  // namespace lbmshape
