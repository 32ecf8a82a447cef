// The level-set shift that keeps a denoise's volume (surface/volume_keeping):
// the ramp count of enclosed voxels, and the shift that restores a count.
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/surface/marching_cubes.hpp"
#include "lbmshape/surface/volume_keeping.hpp"
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

// The triangles' side of keeping the volume: how fast a zero level's volume
// grows as the field is shifted, and the shift that gives the triangles
// the volume wanted.
const GridFrame unitFrame{glm::dvec3(0.0), 1.0, extent};

TEST(VolumeKeeping, TheVolumePerShiftIsTheAreaOverTheGradient)
{
  const Volume distance = sphere(12.0);
  const TriangleMesh level = extractSurface(distance, unitFrame);
  const double area = areaAndSignedVolume(level).area;
  EXPECT_NEAR(volumePerShift(distance, unitFrame, level), area, 0.01 * area);
  // Half the gradient: the surface moves twice as far a shift.
  Volume halved = distance;
  for (float& x : halved.values()) x *= 0.5f;
  EXPECT_NEAR(volumePerShift(halved, unitFrame, level), 2.0 * area, 0.02 * area);
  // In world units: volume per voxel of shift.
  const GridFrame coarse{glm::dvec3(0.0), 0.5, extent};
  const TriangleMesh scaled = extractSurface(distance, coarse);
  EXPECT_NEAR(volumePerShift(distance, coarse, scaled), 0.5 * areaAndSignedVolume(scaled).area,
              0.01 * 0.5 * areaAndSignedVolume(scaled).area);
}

TEST(VolumeKeeping, TheMeshShiftGivesTheTrianglesTheVolumeWanted)
{
  // Marching cubes' chords enclose less than the sphere they cut.
  const double radius = 7.3;
  const double exact = 4.0 / 3.0 * glm::pi<double>() * radius * radius * radius;
  Volume field = sphere(radius);
  const TriangleMesh before = extractSurface(field, unitFrame);
  const double missingBefore = exact - areaAndSignedVolume(before).signedVolume;
  ASSERT_GT(missingBefore, 0.002 * exact) << "the chords' bias this test is about";
  const double d =
      meshVolumeShift(exact, areaAndSignedVolume(before).signedVolume, volumePerShift(field, unitFrame, before), 0.1);
  EXPECT_GT(d, 0.0);
  shiftField(field, d);
  const double after = areaAndSignedVolume(extractSurface(field, unitFrame)).signedVolume;
  EXPECT_NEAR(after, exact, 0.1 * missingBefore);
}

TEST(VolumeKeeping, AVolumeFarOffIsNotTheTrianglesBias)
{
  EXPECT_DOUBLE_EQ(meshVolumeShift(100.0, 95.0, 10.0, 0.1), 0.5);
  EXPECT_DOUBLE_EQ(meshVolumeShift(100.0, 105.0, 10.0, 0.1), -0.5);
  EXPECT_EQ(meshVolumeShift(100.0, 80.0, 10.0, 0.1), 0.0);
  EXPECT_EQ(meshVolumeShift(100.0, 95.0, 0.0, 0.1), 0.0);
}

TEST(VolumeKeeping, TheBandGivesTheGridsVolumePerShift)
{
  const Volume grid = sphere(11.0);
  const BandField band = testing::bandOf(grid, testing::bricksNear(grid, 6.0));
  const TriangleMesh level = extractSurface(grid, unitFrame);
  EXPECT_NEAR(volumePerShift(band, unitFrame, level), volumePerShift(grid, unitFrame, level), 1e-9);
}

}  // namespace
}  // namespace lbmshape
