// Triangles wound against their neighbours and shells inside out are turned
// as the winding number's sign needs; a cavity's inward shell, a clean mesh
// and a one-sided surface are left as they are.
#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/sdf/shell_orientation.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

TriangleMesh turnedOver(TriangleMesh mesh)
{
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

// `mesh` with about `fraction` of its triangles, chosen at random, turned over.
TriangleMesh partlyTurned(TriangleMesh mesh, double fraction, size_t& turned)
{
  std::mt19937 random(11);
  std::bernoulli_distribution pick(fraction);
  turned = 0;
  for (auto& t : mesh.triangles)
    if (pick(random)) std::swap(t[1], t[2]), ++turned;
  return mesh;
}

TEST(ShellOrientation, TrianglesWoundAgainstTheirNeighboursAreTurnedBack)
{
  const TriangleMesh torus = testing::torusMesh(1.0, 0.4, 48, 24);
  for (const double fraction : {0.1, 0.3, 0.45}) {
    size_t turned = 0;
    TriangleMesh mesh = partlyTurned(torus, fraction, turned);
    ASSERT_FALSE(analyzeTopology(mesh).consistentlyOriented);
    const Reorientation r = orientShells(mesh);
    EXPECT_EQ(r.trianglesTurned, turned) << fraction;  // the orientation most had wins
    EXPECT_EQ(r.shellsTurned, 0u);
    EXPECT_EQ(mesh.triangles, torus.triangles) << fraction;
  }
}

TEST(ShellOrientation, AShellInsideOutIsTurnedToFaceOut)
{
  // Mostly inward, some triangles outward: first made to agree (inward, as
  // most are), then the whole shell turned.
  size_t turned = 0;
  TriangleMesh mesh = partlyTurned(turnedOver(testing::icosphere(3)), 0.2, turned);
  const Reorientation r = orientShells(mesh);
  EXPECT_EQ(r.shellsTurned, 1u);
  const MeshTopology t = analyzeTopology(mesh);
  EXPECT_TRUE(t.closedManifold);
  EXPECT_GT(t.signedVolume, 4.0);  // the unit sphere's 4.19, less its facets
}

TEST(ShellOrientation, OnePartInsideOutOfTwoIsTurnedAndACavityIsNot)
{
  const TriangleMesh ball = testing::icosphere(2), other = testing::icosphere(2, 0.5, {3.0, 0.0, 0.0});
  TriangleMesh assembly = testing::merged(ball, turnedOver(other));
  EXPECT_EQ(orientShells(assembly).shellsTurned, 1u);
  EXPECT_EQ(assembly.triangles, testing::merged(ball, other).triangles);

  // A hollow ball: its inner shell faces in on purpose, inside the outer.
  const TriangleMesh hollow = testing::merged(ball, turnedOver(testing::icosphere(2, 0.5)));
  TriangleMesh kept = hollow;
  const Reorientation r = orientShells(kept);
  EXPECT_FALSE(r.changed());
  EXPECT_EQ(kept.triangles, hollow.triangles);
}

// A mirrored hollow part: every shell reversed, so its outer shell faces
// in and its cavity's faces out. Turning the outer alone made it solid;
// the cavity is turned with it, and a ball inside the cavity turned to
// face out again.
TEST(ShellOrientation, AMirroredHollowPartKeepsItsCavity)
{
  const TriangleMesh outer = testing::icosphere(3), cavity = turnedOver(testing::icosphere(3, 0.6)),
                     ball = testing::icosphere(2, 0.3);
  const TriangleMesh hollow = testing::merged(outer, cavity);
  TriangleMesh mirrored = turnedOver(hollow);
  const Reorientation r = orientShells(mirrored);
  EXPECT_EQ(r.shellsTurned, 1u);
  EXPECT_EQ(r.nestedShellsTurned, 1u);
  EXPECT_EQ(mirrored.triangles, hollow.triangles);

  const TriangleMesh nested = testing::merged(hollow, ball);
  TriangleMesh mirroredNest = turnedOver(nested);
  const Reorientation n = orientShells(mirroredNest);
  EXPECT_EQ(n.shellsTurned + n.nestedShellsTurned, 3u);  // the ball, in no other by the sum, is one of the first
  EXPECT_EQ(mirroredNest.triangles, nested.triangles);

  // Only the outer shell reversed (its cavity right): the cavity stays.
  TriangleMesh outerReversed = testing::merged(turnedOver(outer), cavity);
  const Reorientation o = orientShells(outerReversed);
  EXPECT_EQ(o.shellsTurned, 1u);
  EXPECT_EQ(o.nestedShellsTurned, 0u);
  EXPECT_EQ(outerReversed.triangles, hollow.triangles);
}

// A mirrored scan (open, every triangle reversed) has a winding number of
// about -1 inside and enclosed nothing: turned. A sheet either way up and a
// scan the right way out are left.
TEST(ShellOrientation, AnOpenScanInsideOutIsTurned)
{
  TriangleMesh scan;  // a sphere with its top cap missing
  const TriangleMesh sphere = testing::icosphere(3);
  scan.positions = sphere.positions;
  for (const glm::uvec3& t : sphere.triangles)
    if (sphere.positions[t.x].z + sphere.positions[t.y].z + sphere.positions[t.z].z < 2.4) scan.triangles.push_back(t);
  TriangleMesh mirrored = turnedOver(scan);
  const Reorientation r = orientShells(mirrored);
  EXPECT_EQ(r.openPiecesTurned, 1u);
  EXPECT_EQ(mirrored.triangles, scan.triangles);
  TriangleMesh right = scan;
  EXPECT_FALSE(orientShells(right).changed());

  const TriangleMesh sheet =
      testing::sheet(12, [](double u, double v) { return glm::dvec3(u, v, 0.3 * std::sin(3.0 * u)); });
  for (const TriangleMesh& way : {sheet, turnedOver(sheet)}) {
    TriangleMesh kept = way;
    EXPECT_EQ(orientShells(kept).openPiecesTurned, 0u);
    EXPECT_EQ(kept.triangles, way.triangles);
  }
}

// A ball reversed with a pin (a long box) pushed through its poles: the
// ball is partly inside the pin, not a cavity, and is turned, whichever of
// its triangles comes first in the file (one, the first, decided it); the
// pin reversed instead is turned and the ball left, not taken for a cavity
// of the pin.
TEST(ShellOrientation, AShellPushedThroughAnotherIsNoCavityInAnyOrder)
{
  const TriangleMesh ball = testing::icosphere(3), pin = testing::box({-0.2, -0.2, -1.5}, {0.2, 0.2, 1.5});
  for (const bool reverseTheBall : {true, false}) {
    const TriangleMesh right = testing::merged(ball, pin);
    TriangleMesh assembly =
        reverseTheBall ? testing::merged(turnedOver(ball), pin) : testing::merged(ball, turnedOver(pin));
    std::mt19937 random(3);
    for (int order = 0; order < 3; ++order) {
      TriangleMesh shuffled = assembly;
      std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end(), random);
      const Reorientation r = orientShells(shuffled);
      EXPECT_EQ(r.shellsTurned, 1u) << reverseTheBall << " " << order;
      EXPECT_EQ(r.nestedShellsTurned, 0u) << reverseTheBall << " " << order;
      EXPECT_GT(analyzeTopology(shuffled).signedVolume, analyzeTopology(right).signedVolume - 1e-9);
      EXPECT_NEAR(analyzeTopology(shuffled).signedVolume, analyzeTopology(right).signedVolume, 1e-9);
    }
  }
}

// A hollow ball with a hole through both walls: its outer wall faces out,
// its inner wall in, as they should; both open. The inner wall alone has a
// winding number of -1 at its centroid, but inside the outer wall the whole
// mesh has 0 there: it is left (it was turned, and the cavity filled). The
// same scan cut in patches, every patch reversed, is turned as a whole.
TEST(ShellOrientation, AnOpenInnerWallIsLeftAndAScanInPatchesIsTurned)
{
  const auto cut = [](const TriangleMesh& sphere, const std::function<bool(const glm::dvec3&)>& keep) {
    TriangleMesh kept;
    kept.positions = sphere.positions;
    for (const glm::uvec3& t : sphere.triangles)
      if (keep((sphere.positions[t.x] + sphere.positions[t.y] + sphere.positions[t.z]) / 3.0))
        kept.triangles.push_back(t);
    return kept;
  };
  const auto awayFromTheHole = [](const glm::dvec3& c) { return c.z < 0.9 * glm::length(c); };
  const TriangleMesh holed = testing::merged(cut(testing::icosphere(3), awayFromTheHole),
                                             turnedOver(cut(testing::icosphere(3, 0.6), awayFromTheHole)));
  TriangleMesh kept = holed;
  EXPECT_EQ(orientShells(kept).openPiecesTurned, 0u);
  EXPECT_EQ(kept.triangles, holed.triangles);

  // Four patches of a sphere (quadrants in x and y, apart), each reversed.
  const TriangleMesh sphere = testing::icosphere(3);
  TriangleMesh patches;
  patches.positions = sphere.positions;
  for (const bool east : {false, true})
    for (const bool north : {false, true}) {
      const TriangleMesh quadrant = turnedOver(cut(sphere, [&](const glm::dvec3& c) {
        return (c.x > 0.0) == east && (c.y > 0.0) == north && std::abs(c.x) > 0.06 && std::abs(c.y) > 0.06;
      }));
      patches.triangles.insert(patches.triangles.end(), quadrant.triangles.begin(), quadrant.triangles.end());
    }
  const Reorientation r = orientShells(patches);
  EXPECT_EQ(r.openPiecesTurned, 4u);
  EXPECT_GT(analyzeTopology(patches).signedVolume, 3.0);
}

TEST(ShellOrientation, AnOpenSheetKeepsTheWayMostOfItFaced)
{
  const TriangleMesh sheet =
      testing::sheet(12, [](double u, double v) { return glm::dvec3(u, v, 0.1 * std::sin(3.0 * u)); });
  size_t turned = 0;
  TriangleMesh mesh = partlyTurned(sheet, 0.25, turned);
  const Reorientation r = orientShells(mesh);
  EXPECT_EQ(r.trianglesTurned, turned);
  EXPECT_EQ(r.shellsTurned, 0u);  // open: it has no inside to face
  EXPECT_EQ(mesh.triangles, sheet.triangles);
}

TEST(ShellOrientation, AOneSidedSurfaceIsCountedAndLeftWhole)
{
  // A Möbius strip: a band of 24 x 2 quads whose ends join with a half twist.
  TriangleMesh strip;
  const int n = 24;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 3; ++j) {
      const double a = 2.0 * M_PI * i / n, w = (j - 1) * 0.3;
      strip.positions.push_back(
          {(1.0 + w * std::cos(a / 2)) * std::cos(a), (1.0 + w * std::cos(a / 2)) * std::sin(a), w * std::sin(a / 2)});
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2; ++j) {
      const uint32_t a = 3 * i + j, b = 3 * i + j + 1;
      // The last column joins the first upside down.
      const uint32_t c = i + 1 < n ? 3 * (i + 1) + j : uint32_t(2 - j), d = i + 1 < n ? 3 * (i + 1) + j + 1 : 1 - j;
      strip.triangles.push_back({a, c, b});
      strip.triangles.push_back({b, c, d});
    }
  const size_t triangles = strip.triangleCount();
  const Reorientation r = orientShells(strip);
  EXPECT_GT(r.unorientableEdges, 0u);
  EXPECT_EQ(strip.triangleCount(), triangles);
}

TEST(ShellOrientation, ACleanMeshIsLeftAlone)
{
  TriangleMesh torus = testing::torusMesh(1.0, 0.4, 32, 16);
  const TriangleMesh before = torus;
  EXPECT_FALSE(orientShells(torus).changed());
  EXPECT_EQ(torus.triangles, before.triangles);
}

}  // namespace
}  // namespace lbmshape
