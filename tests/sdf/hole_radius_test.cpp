// The widest hole's radius, which widens the narrow band over an open
// mesh's holes (sdf/hole_radius.hpp).
#include <gtest/gtest.h>

#include "lbmshape/sdf/hole_radius.hpp"
#include "sdf_fixtures.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

TEST(HoleRadius, AClosedMeshHasNone)
{
  EXPECT_EQ(widestHoleRadius(testing::icosphere(3, 1.0)), 0.0);
  EXPECT_EQ(widestHoleRadius(testing::torusMesh(1.0, 0.3, 32, 16)), 0.0);
  EXPECT_EQ(halfWidthOverHoles(testing::icosphere(3, 1.0), 0.01, 7.0), 7.0);
}

TEST(HoleRadius, AHemispheresHoleIsItsRim)
{
  const TriangleMesh half = testing::upperHalf(testing::icosphere(4, 2.0));
  EXPECT_NEAR(widestHoleRadius(half), 2.0, 0.1);  // the rim zigzags about the equator
  // In voxels of 0.1: 20 and a quarter, and one.
  EXPECT_GE(halfWidthOverHoles(half, 0.1, 7.0), 26.0);
  EXPECT_LE(halfWidthOverHoles(half, 0.1, 7.0), 28.0);
  EXPECT_EQ(halfWidthOverHoles(half, 0.1, 40.0), 40.0);  // already wide enough
}

TEST(HoleRadius, TheWidestOfSeveralHolesCounts)
{
  // Small holes, one triangle each: as wide as a triangle.
  const TriangleMesh sphere = testing::icosphere(4, 1.0);
  const TriangleMesh pitted = testing::sdf::withHoles(sphere, 5, 3);
  const double pit = widestHoleRadius(pitted);
  EXPECT_GT(pit, 0.0);
  EXPECT_LT(pit, 0.1);
  // With a wide one beside them (the lower cap cut off at z = -0.8).
  TriangleMesh cut;
  cut.positions = pitted.positions;
  for (const glm::uvec3& t : pitted.triangles)
    if (pitted.positions[t.x].z + pitted.positions[t.y].z + pitted.positions[t.z].z > -2.4) cut.triangles.push_back(t);
  EXPECT_NEAR(widestHoleRadius(cut), 0.6, 0.06);  // sqrt(1 - 0.8^2)
}

}  // namespace
}  // namespace lbmshape
