// The widest hole's radius, which widens the narrow band over an open
// mesh's holes (sdf/hole_radius.hpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/sdf/hole_radius.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
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

TEST(ClosingFans, AClosedMeshHasNone) { EXPECT_TRUE(closingFans(testing::icosphere(3, 1.0)).mesh.triangles.empty()); }

// A hemisphere's film is the disk its rim bounds (the winding number is 1/2
// on it): the fan lies there, one triangle per rim edge, and is nearly flat.
TEST(ClosingFans, AHemispheresFanIsTheDiskWhereTheWindingNumberIsAHalf)
{
  const TriangleMesh half = testing::upperHalf(testing::icosphere(4, 2.0));
  const ClosingFans fans = closingFans(half);
  EXPECT_EQ(fans.mesh.triangles.size(), analyzeTopology(half).boundaryEdges);
  EXPECT_LT(fans.farthestOffPlane, 0.2);  // the rim zigzags about the equator
  const TriangleBvh tree(half);
  for (size_t t = 0; t < fans.mesh.triangles.size(); t += 7) {
    const glm::uvec3 f = fans.mesh.triangles[t];
    // Half way from the rim to the centre: far from the rim's zigzag.
    const glm::dvec3 p = 0.25 * (fans.mesh.positions[f.x] + fans.mesh.positions[f.y]) + 0.5 * fans.mesh.positions[f.z];
    EXPECT_NEAR(tree.windingNumber(p), 0.5, 0.05) << "fan triangle " << t;
    EXPECT_NEAR(p.z, 0.0, 0.1);
  }
}

// A T-junction: an edge one face runs whole and the faces beside it run in
// two halves. Its "rim" encloses nothing, and gets no fan (which would only
// fill the solid with bricks), however little area is asked for.
TEST(ClosingFans, ATJunctionEnclosesNothingAndGetsNoFan)
{
  TriangleMesh tetra;
  tetra.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0, 0}};
  // Outward tetrahedron, the face (0, 2, 1) split at 4, the middle of edge 0-1.
  tetra.triangles = {{0, 2, 4}, {4, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  EXPECT_GT(analyzeTopology(tetra).boundaryEdges, 0u);
  EXPECT_TRUE(closingFans(tetra, 1e-12).mesh.triangles.empty());
  EXPECT_TRUE(closingFans(tetra, 0.0).mesh.triangles.empty());
}

// An open box (its top missing) whose side edges carry T-junctions: they
// join the top's rim through its corners, and the fan from all their
// vertices' centroid, the box's centre, would fill the box. The winding
// number there is 5/6, not 1/2: no fan (the band widens if it must).
TEST(ClosingFans, AnOpenBoxWithTJunctionsGetsNoFanThroughItsInside)
{
  TriangleMesh box;
  // Corners of a unit cube, then the middle of each vertical edge.
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) box.positions.emplace_back(x, y, z);
  const auto corner = [](int x, int y, int z) { return uint32_t(x + 2 * y + 4 * z); };
  // The bottom, facing down.
  box.triangles = {{corner(0, 0, 0), corner(0, 1, 0), corner(1, 1, 0)},
                   {corner(0, 0, 0), corner(1, 1, 0), corner(1, 0, 0)}};
  // Each side as two triangles (its vertical edges whole), then the same
  // sides split at their edges' middles on one side only: T-junctions.
  const glm::ivec2 around[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 4; ++k) {
    const glm::ivec2 a = around[k], b = around[(k + 1) % 4];
    const uint32_t a0 = corner(a.x, a.y, 0), b0 = corner(b.x, b.y, 0), a1 = corner(a.x, a.y, 1),
                   b1 = corner(b.x, b.y, 1);
    const auto middle = uint32_t(box.positions.size());
    box.positions.emplace_back(b.x, b.y, 0.5);  // on edge b0-b1, used by this side only
    box.triangles.push_back({a0, b0, middle});
    box.triangles.push_back({a0, middle, b1});
    box.triangles.push_back({a0, b1, a1});
  }
  const TriangleBvh tree(box);
  EXPECT_NEAR(tree.windingNumber({0.5, 0.5, 0.5}), 5.0 / 6.0, 0.01);
  EXPECT_FALSE(closingFans(box, 0.0).mesh.triangles.empty()) << "without the winding number, a fan";
  EXPECT_TRUE(closingFans(box, 0.0, [&](const glm::dvec3& p) { return tree.windingNumber(p); }).mesh.triangles.empty());
}

// Two halves of a sphere 1e-7 apart, each numbering its own equator: two
// "rims" with the whole cross-section's area, and no hole. The winding
// number at each fan's centre is 1 (inside the sphere), not 1/2: no fans.
TEST(ClosingFans, ACrackBetweenPiecesGetsNone)
{
  TriangleMesh split = testing::upperHalf(testing::icosphere(3));
  const TriangleMesh lower = testing::lowerHalf(testing::icosphere(3));
  const auto offset = uint32_t(split.positions.size());
  for (const glm::dvec3& p : lower.positions) split.positions.push_back(p - glm::dvec3(0.0, 0.0, 1e-7));
  for (const glm::uvec3& t : lower.triangles) split.triangles.push_back(t + offset);
  EXPECT_FALSE(closingFans(split, 0.0).mesh.triangles.empty()) << "without the winding number, fans";
  const TriangleBvh tree(split);
  EXPECT_TRUE(
      closingFans(split, 0.0, [&](const glm::dvec3& p) { return tree.windingNumber(p); }).mesh.triangles.empty());
  // A hemisphere's own rim keeps its fan with the winding number asked.
  const TriangleMesh half = testing::upperHalf(testing::icosphere(3));
  const TriangleBvh halfTree(half);
  EXPECT_FALSE(
      closingFans(half, 0.0, [&](const glm::dvec3& p) { return halfTree.windingNumber(p); }).mesh.triangles.empty());
}

// Two open caps apart: two rims, two fans, each over its own rim.
TEST(ClosingFans, EachRimHasItsOwnFan)
{
  TriangleMesh tube = testing::upperHalf(testing::icosphere(4, 1.0));
  const TriangleMesh lower = testing::lowerHalf(testing::icosphere(4, 1.0));
  // Two separate caps, each open: two rims apart, the lower 5 below.
  const auto offset = uint32_t(tube.positions.size());
  for (const glm::dvec3& p : lower.positions) tube.positions.push_back(p - glm::dvec3(0.0, 0.0, 5.0));
  for (const glm::uvec3& t : lower.triangles) tube.triangles.push_back(t + offset);
  const ClosingFans fans = closingFans(tube);
  std::vector<double> centres;
  for (const glm::uvec3& t : fans.mesh.triangles) centres.push_back(fans.mesh.positions[t.z].z);
  std::sort(centres.begin(), centres.end());
  centres.erase(std::unique(centres.begin(), centres.end()), centres.end());
  ASSERT_EQ(centres.size(), 2u);
  EXPECT_NEAR(centres[0], -5.0, 0.05);
  EXPECT_NEAR(centres[1], 0.0, 0.05);
}

}  // namespace
}  // namespace lbmshape
