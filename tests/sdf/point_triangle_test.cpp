// The two per-triangle primitives against independent formulas, including
// the degenerate triangles a real mesh soup contains.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "lbmshape/sdf/point_triangle.hpp"
#include "support/test_meshes.hpp"

#include "sdf_fixtures.hpp"

namespace lbmshape {
namespace {

TriangleMesh single(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  TriangleMesh mesh;
  mesh.positions = {a, b, c};
  mesh.triangles = {{0, 1, 2}};
  return mesh;
}

// Slivers are answered by their edges, which moves the point by at most the
// sliver's width (1e-9 here): hence the looser tolerance for them. The
// prepared form (PreparedTriangle, for many queries of one triangle) is held
// to the same oracle, and to the one-query form's point.
void expectMatchesOracle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, std::mt19937& rng,
                         double tolerance = 1e-12)
{
  const TriangleMesh mesh = single(a, b, c);
  const PreparedTriangle prepared(a, b, c);
  for (int k = 0; k < 200; ++k) {
    const glm::dvec3 p = testing::sdf::randomPoint(rng, 2.0);
    const glm::dvec3 q = closestPointOnTriangle(p, a, b, c);
    const double oracle = testing::sdf::bruteForceDistance(mesh, p);
    ASSERT_NEAR(glm::length(q - p), oracle, tolerance)
        << "triangle (" << a.x << " " << a.y << " " << a.z << ") ... point " << p.x << " " << p.y << " " << p.z;
    // The point returned is on the triangle: it is its own closest point.
    EXPECT_LT(testing::sdf::bruteForceDistance(mesh, q), tolerance);
    ASSERT_NEAR(std::sqrt(prepared.distance2(p)), oracle, tolerance) << "prepared, point " << p.x << " " << p.y;
    EXPECT_LT(glm::length(prepared.closestPoint(p) - q), tolerance);
  }
}

TEST(ClosestPointOnTriangle, MatchesProjectionOracleOnRandomTriangles)
{
  std::mt19937 rng(1);
  for (int t = 0; t < 200; ++t) {
    const glm::dvec3 a = testing::sdf::randomPoint(rng, 1.0), b = testing::sdf::randomPoint(rng, 1.0),
                     c = testing::sdf::randomPoint(rng, 1.0);
    expectMatchesOracle(a, b, c, rng);
  }
}

TEST(ClosestPointOnTriangle, HandlesDegenerateTriangles)
{
  std::mt19937 rng(2);
  const glm::dvec3 a(0.1, 0.2, 0.3), b(0.7, -0.4, 0.5), c(-0.3, 0.6, -0.2);
  expectMatchesOracle(a, a, a, rng);  // a point
  expectMatchesOracle(a, a, b, rng);  // a segment, twice
  expectMatchesOracle(a, b, a, rng);
  expectMatchesOracle(a, b, 0.5 * (a + b), rng);                         // collinear, middle vertex last
  expectMatchesOracle(a, 0.25 * a + 0.75 * b, b, rng);                   // collinear, in order
  expectMatchesOracle(a, b, b + 1e-9 * (c - a), rng, 1e-8);              // a needle
  expectMatchesOracle(a, b, 0.5 * (a + b) + 1e-9 * (c - a), rng, 1e-8);  // a sliver
}

TEST(ClosestPointOnTriangle, IsExactAtVerticesEdgesAndInside)
{
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(closestPointOnTriangle({-1, -1, 0}, a, b, c), a);
  EXPECT_EQ(closestPointOnTriangle({2, -0.5, 3}, a, b, c), b);
  EXPECT_EQ(closestPointOnTriangle({0.5, -2, 0}, a, b, c), glm::dvec3(0.5, 0, 0));
  EXPECT_EQ(closestPointOnTriangle({0.25, 0.25, -7}, a, b, c), glm::dvec3(0.25, 0.25, 0));
}

TEST(SolidAngle, SumsToFourPiInsideAClosedSurfaceAndZeroOutside)
{
  const TriangleMesh sphere = testing::icosphere(2, 1.0);
  std::mt19937 rng(3);
  for (int k = 0; k < 50; ++k) {
    const glm::dvec3 p = testing::sdf::randomPoint(rng, 1.5);
    double sum = 0.0;
    for (const auto& t : sphere.triangles)
      sum += solidAngle(p, sphere.positions[t.x], sphere.positions[t.y], sphere.positions[t.z]);
    const double radius = glm::length(p);
    if (radius < 0.9) {
      EXPECT_NEAR(sum, 4.0 * std::numbers::pi, 1e-9);
    } else if (radius > 1.01) {
      EXPECT_NEAR(sum, 0.0, 1e-9);
    }
  }
}

TEST(SolidAngle, MatchesSphericalExcessOracle)
{
  std::mt19937 rng(4);
  for (int k = 0; k < 500; ++k) {
    const glm::dvec3 a = testing::sdf::randomPoint(rng, 1.0), b = testing::sdf::randomPoint(rng, 1.0),
                     c = testing::sdf::randomPoint(rng, 1.0);
    const glm::dvec3 p = testing::sdf::randomPoint(rng, 1.0);
    EXPECT_NEAR(solidAngle(p, a, b, c) / (4.0 * std::numbers::pi),
                testing::sdf::bruteForceWindingNumber(single(a, b, c), p), 1e-9);
  }
}

}  // namespace
}  // namespace lbmshape
