// Marching cubes in two halves (surface_pieces.hpp): the pieces listed from
// a band, assembled, give extractSurface()'s mesh on that band: the same
// vertices and triangles in the same order.
#include <algorithm>
#include <limits>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/surface/band_marching_cubes.hpp"
#include "lbmshape/surface/surface_pieces.hpp"
#include "support/band_fields.hpp"
#include "support/implicit_fields.hpp"

namespace lbmshape {
namespace {

void expectSameMesh(const TriangleMesh& got, const TriangleMesh& expected)
{
  ASSERT_EQ(got.vertexCount(), expected.vertexCount());
  ASSERT_EQ(got.triangleCount(), expected.triangleCount());
  EXPECT_EQ(got.positions, expected.positions);
  EXPECT_EQ(got.normals, expected.normals);
  EXPECT_EQ(got.triangles, expected.triangles);
}

// A torus and a sphere that touch (saddles, thin necks) on a grid whose far
// bricks are partly beyond it.
Volume touchingShapes(const GridFrame& frame)
{
  return testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    return std::max(testing::torusSdf(p, {0.0, 0.0, 0.0}, 6.0, 2.0), testing::sphereSdf(p, {6.0, 2.0, 3.0}, 3.5));
  });
}

TEST(SurfacePieces, AssembledTheyAreTheBandsMesh)
{
  const GridFrame frame = testing::cubicFrame({41, 38, 45}, 0.5, {-10.0, -9.0, -11.0});
  const Volume field = touchingShapes(frame);
  for (const double reach : {3.0, 0.5}) {  // 0.5: cubes that reach into bricks not stored (their far values)
    const BandField band = testing::bandOf(field, testing::bricksNear(field, reach));
    const SurfacePieces pieces = listSurfacePieces(band);
    const TriangleMesh got = assembleSurface(pieces, frame);
    SCOPED_TRACE("reach " + std::to_string(reach));
    expectSameMesh(got, extractSurface(band, frame));
    // Closed where the band holds every cube the surface passes through.
    if (reach >= 2.0) {
      EXPECT_TRUE(analyzeTopology(got).closedManifold);
    }
    EXPECT_FALSE(pieces.errorNearBase) << "none asked for";
  }
}

TEST(SurfacePieces, ASurfaceThatLeavesTheGridIsOpenAsTheBandsMeshIs)
{
  const GridFrame frame = testing::cubicFrame({17, 20, 25}, 1.0);
  const Volume field = testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    return testing::sphereSdf(p, {8.0, 0.0, 24.0}, 9.2);
  });
  const BandField band = testing::bandOf(field, testing::bricksNear(field, 2.0));
  expectSameMesh(assembleSurface(listSurfacePieces(band), frame), extractSurface(band, frame));
}

TEST(SurfacePieces, AnotherIsovalueGivesItsOwnSurface)
{
  const GridFrame frame = testing::cubicFrame({30, 30, 30}, 1.0);
  const Volume field = testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    return testing::sphereSdf(p, {14.3, 15.1, 14.7}, 9.0);
  });
  const BandField band = testing::bandOf(field, testing::bricksNear(field, 4.0));
  const TriangleMesh zero = assembleSurface(listSurfacePieces(band), frame);
  const TriangleMesh shifted = assembleSurface(listSurfacePieces(band, {.isovalue = 1.5f}), frame);
  expectSameMesh(shifted, extractSurface(band, frame, 1.5f));
  EXPECT_LT(shifted.vertexCount(), zero.vertexCount()) << "a smaller sphere";
}

TEST(SurfacePieces, TheErrorNearTheBaseIsTheLargestDifferenceWhereTheBaseIsSmall)
{
  const GridFrame frame = testing::cubicFrame({24, 24, 24}, 1.0);
  const Volume field = testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    return testing::sphereSdf(p, {11.5, 12.2, 11.8}, 7.0);
  });
  const BandField band = testing::bandOf(field, testing::bricksNear(field, 3.0));
  BandField base = band;
  double expected = 0.0;
  for (size_t i = 0; i < base.values().size(); ++i) {
    base.values()[i] += 0.001f * float(i % 97);
    if (std::abs(base.values()[i]) <= 1.0f)
      expected = std::max(expected, double(std::abs(band.values()[i] - base.values()[i])));
  }
  const SurfacePieces pieces = listSurfacePieces(band, {.nearBand = 1.0f}, &base);
  ASSERT_TRUE(pieces.errorNearBase);
  EXPECT_EQ(*pieces.errorNearBase, expected);
  EXPECT_GT(expected, 0.05);
  EXPECT_EQ(*listSurfacePieces(band, {.nearBand = 1.0f}, &band).errorNearBase, 0.0);
}

TEST(SurfacePieces, ProbesReadTheFieldStoredOrNot)
{
  const GridFrame frame = testing::cubicFrame({30, 30, 30}, 1.0);
  const Volume field = testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    return testing::sphereSdf(p, {14.3, 15.1, 14.7}, 9.0);
  });
  const BandField band = testing::bandOf(field, testing::bricksNear(field, 2.0));
  const SurfaceRequest request{.probes = {{0, 0, 0}, {14, 15, 15}, {14, 15, 5}, {29, 29, 29}}};
  const SurfacePieces pieces = listSurfacePieces(band, request);
  ASSERT_EQ(pieces.probeValues.size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    const glm::ivec3 c = request.probes[k];
    EXPECT_EQ(pieces.probeValues[k], band.at(c.x, c.y, c.z)) << k;
  }
  EXPECT_LT(pieces.probeValues[0], -8.0f) << "far outside, not stored";
  EXPECT_GT(pieces.probeValues[1], 8.0f) << "far inside, not stored";
  EXPECT_THROW(listSurfacePieces(band, {.probes = {{0, 30, 0}}}), std::invalid_argument);
}

TEST(SurfacePieces, RefusesAValueThatIsNotAFiniteNumber)
{
  const GridFrame frame = testing::cubicFrame({20, 20, 20}, 1.0);
  const Volume field = testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    return testing::sphereSdf(p, {9.6, 10.2, 9.9}, 6.3);
  });
  BandField band = testing::bandOf(field, testing::bricksNear(field, 2.0));
  ASSERT_NO_THROW(listSurfacePieces(band));
  band.values().back() = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(listSurfacePieces(band), NumericalError);
}

TEST(SurfacePieces, ACubeWhoseEdgeIsMissingIsRefused)
{
  const GridFrame frame = testing::cubicFrame({20, 20, 20}, 1.0);
  const Volume field = testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    return testing::sphereSdf(p, {9.6, 10.2, 9.9}, 6.3);
  });
  SurfacePieces pieces = listSurfacePieces(testing::bandOf(field, testing::bricksNear(field, 2.0)));
  ASSERT_NO_THROW(assembleSurface(pieces, frame));
  pieces.crossings.erase(pieces.crossings.begin() + ptrdiff_t(pieces.crossings.size() / 2));
  EXPECT_THROW(assembleSurface(pieces, frame), NumericalError);
  EXPECT_THROW(assembleSurface(pieces, testing::cubicFrame({20, 20, 21}, 1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace lbmshape
