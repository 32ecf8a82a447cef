// TriangleBvh against brute force: closest points on soups with degenerate
// and overlapping triangles, the bounded search, and the fast winding number.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lbmshape/core/error.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
#include "support/test_meshes.hpp"

#include "sdf_fixtures.hpp"

namespace lbmshape {
namespace {

// Small random triangles scattered in a cube, some of them degenerate: no
// structure a hierarchy could lean on.
TriangleMesh randomSoup(size_t count, uint32_t seed)
{
  std::mt19937 rng(seed);
  TriangleMesh mesh;
  for (size_t t = 0; t < count; ++t) {
    const glm::dvec3 c = testing::sdf::randomPoint(rng, 1.0);
    const uint32_t v = uint32_t(mesh.positions.size());
    mesh.positions.push_back(c + testing::sdf::randomPoint(rng, 0.1));
    mesh.positions.push_back(t % 17 == 0 ? mesh.positions.back()
                                         : c + testing::sdf::randomPoint(rng, 0.1));          // repeated vertex
    mesh.positions.push_back(t % 13 == 0 ? 0.5 * (mesh.positions[v] + mesh.positions[v + 1])  // collinear
                                         : c + testing::sdf::randomPoint(rng, 0.1));
    mesh.triangles.push_back({v, v + 1, v + 2});
  }
  return mesh;
}

TEST(TriangleBvh, ClosestMatchesBruteForce)
{
  const TriangleMesh meshes[] = {randomSoup(3000, 1), testing::icosphere(3, 0.7),
                                 testing::box({-1, -1, -1}, {1, 1, 1})};
  for (const TriangleMesh& mesh : meshes) {
    const TriangleBvh bvh(mesh);
    std::mt19937 rng(2);
    for (int k = 0; k < 300; ++k) {
      const glm::dvec3 p = testing::sdf::randomPoint(rng, k % 3 == 0 ? 4.0 : 1.2);
      const TriangleBvh::Closest c = bvh.closest(p);
      ASSERT_NEAR(c.distance, testing::sdf::bruteForceDistance(mesh, p), 1e-12);
      EXPECT_NEAR(glm::length(c.point - p), c.distance, 1e-12);
      ASSERT_LT(c.triangle, mesh.triangles.size());
      // The triangle reported is the mesh's, and the point is on it.
      TriangleMesh one;
      one.positions = mesh.positions;
      one.triangles = {mesh.triangles[c.triangle]};
      EXPECT_NEAR(testing::sdf::bruteForceDistance(one, p), c.distance, 1e-12);
      EXPECT_LT(testing::sdf::bruteForceDistance(one, c.point), 1e-12);
      EXPECT_NEAR(bvh.closestOnTriangle(p, c.triangle).distance, c.distance, 1e-15);
    }
  }
}

TEST(TriangleBvh, BoundedSearchIsExactWithinTheBoundAndEmptyBeyondIt)
{
  const TriangleMesh mesh = randomSoup(2000, 3);
  const TriangleBvh bvh(mesh);
  std::mt19937 rng(4);
  for (int k = 0; k < 300; ++k) {
    const glm::dvec3 p = testing::sdf::randomPoint(rng, 1.5);
    const double exact = testing::sdf::bruteForceDistance(mesh, p);
    EXPECT_NEAR(bvh.closest(p, exact).distance, exact, 1e-12);  // a bound equal to the answer still finds it
    EXPECT_NEAR(bvh.closest(p, exact * 1.5 + 0.01).distance, exact, 1e-12);
    const TriangleBvh::Closest none = bvh.closest(p, exact * 0.99);
    EXPECT_EQ(none.triangle, TriangleBvh::kNoTriangle);
    EXPECT_TRUE(std::isinf(none.distance));
  }
}

TEST(TriangleBvh, ExactWindingNumberIsOneInsideAndZeroOutside)
{
  const TriangleMesh sphere = testing::icosphere(3, 1.0);
  const TriangleBvh bvh(sphere);
  EXPECT_NEAR(bvh.exactWindingNumber({0.1, -0.2, 0.3}), 1.0, 1e-12);
  EXPECT_NEAR(bvh.exactWindingNumber({0.0, 0.0, 0.97}), 1.0, 1e-9);
  EXPECT_NEAR(bvh.exactWindingNumber({1.2, 0.5, 0.0}), 0.0, 1e-12);
  EXPECT_NEAR(bvh.exactWindingNumber({30.0, -20.0, 10.0}), 0.0, 1e-12);
}

// Barill et al.'s approximation against the exact sum, at points spread over
// and around each mesh (but not on it), on closed, open and soup inputs.
TEST(TriangleBvh, FastWindingNumberMatchesExactAwayFromTheSurface)
{
  const TriangleMesh sphere = testing::icosphere(4, 1.0);
  const TriangleMesh meshes[] = {sphere, testing::sdf::withHoles(sphere, 60, 5),
                                 testing::merged(sphere, testing::icosphere(3, 0.6, {0.8, 0.2, 0.0})),
                                 randomSoup(4000, 6)};
  for (const TriangleMesh& mesh : meshes) {
    const TriangleBvh bvh(mesh);
    std::mt19937 rng(7);
    double worst = 0.0, sum = 0.0;
    int counted = 0;
    for (int k = 0; k < 400; ++k) {
      const glm::dvec3 p = testing::sdf::randomPoint(rng, 1.6);
      if (bvh.closest(p).distance < 0.01) continue;  // within about 1/200 of the size of the mesh
      const double error = std::abs(bvh.windingNumber(p) - bvh.exactWindingNumber(p));
      worst = std::max(worst, error);
      sum += error;
      ++counted;
    }
    std::cout << "fast winding number on " << mesh.triangles.size() << " triangles: mean error " << sum / counted
              << ", worst " << worst << " over " << counted << " points\n";
    EXPECT_LT(worst, 2e-3);
    EXPECT_LT(sum / counted, 3e-4);
  }
}

TEST(TriangleBvh, ExactWindingNumberAgreesWithSphericalExcessOracle)
{
  const TriangleMesh mesh = testing::sdf::withHoles(testing::icosphere(2, 1.0), 10, 8);
  const TriangleBvh bvh(mesh);
  std::mt19937 rng(9);
  for (int k = 0; k < 100; ++k) {
    const glm::dvec3 p = testing::sdf::randomPoint(rng, 1.5);
    EXPECT_NEAR(bvh.exactWindingNumber(p), testing::sdf::bruteForceWindingNumber(mesh, p), 1e-9);
  }
}

TEST(TriangleBvh, EmptyMeshHasNoSurface)
{
  const TriangleBvh bvh{TriangleMesh{}};
  const TriangleBvh::Closest c = bvh.closest({1, 2, 3});
  EXPECT_EQ(c.triangle, TriangleBvh::kNoTriangle);
  EXPECT_TRUE(std::isinf(c.distance));
  EXPECT_EQ(bvh.windingNumber({1, 2, 3}), 0.0);
  EXPECT_EQ(bvh.exactWindingNumber({1, 2, 3}), 0.0);
}

TEST(TriangleBvh, SingleTriangleAndCoincidentTriangles)
{
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  EXPECT_NEAR(TriangleBvh(mesh).closest({0.2, 0.2, 0.5}).distance, 0.5, 1e-15);
  // Many copies of one triangle (all centroids equal): the build must still split.
  mesh.triangles.assign(1000, {0, 1, 2});
  const TriangleBvh copies(mesh);
  EXPECT_NEAR(copies.closest({0.2, 0.2, 0.5}).distance, 0.5, 1e-15);
  EXPECT_NEAR(copies.exactWindingNumber({0.2, 0.2, 0.5}), copies.windingNumber({0.2, 0.2, 0.5}), 1e-9);
}

TEST(TriangleBvh, RejectsBadIndicesAndPositions)
{
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 3}};
  EXPECT_THROW(TriangleBvh{mesh}, InputError);
  mesh.triangles = {{0, 1, 2}};
  mesh.positions[1].y = std::nan("");
  EXPECT_THROW(TriangleBvh{mesh}, InputError);
}

}  // namespace
}  // namespace lbmshape
