// Test-input noise: Gaussian along the normals, of the asked size, and the
// same for the same seed.
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include <gtest/gtest.h>

#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;

TEST(MeanEdgeLength, OfATriangulatedCube)
{
  // Every triangle has two unit edges and a diagonal of sqrt(2).
  EXPECT_NEAR(meanEdgeLength(testing::box({0, 0, 0}, {1, 1, 1})), (2.0 + std::sqrt(2.0)) / 3.0, 1e-12);
  EXPECT_NEAR(meanEdgeLength(testing::box({0, 0, 0}, {3, 3, 3})), (2.0 + std::sqrt(2.0)), 1e-12);
  EXPECT_EQ(meanEdgeLength(TriangleMesh{}), 0.0);
}

TEST(Noise, SameSeedSameMeshOtherSeedOtherMesh)
{
  const TriangleMesh sphere = testing::icosphere(3);
  const TriangleMesh a = addNormalNoise(sphere, 0.2, 42), b = addNormalNoise(sphere, 0.2, 42),
                     c = addNormalNoise(sphere, 0.2, 43);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_NE(a.positions, c.positions);
  EXPECT_EQ(a.triangles, sphere.triangles);
  EXPECT_TRUE(a.normals.empty());
}

TEST(Noise, MovesAlongTheNormalsByTheAskedSigma)
{
  const TriangleMesh sphere = testing::icosphere(4, 2.0);  // 2562 vertices
  const double sigma = 0.25 * meanEdgeLength(sphere);
  const TriangleMesh noisy = addNormalNoise(sphere, 0.25, 7);
  const auto normals = areaWeightedNormals(sphere);
  double sumMagnitude = 0, sumSigned = 0, sumSquares = 0;
  for (size_t i = 0; i < sphere.positions.size(); ++i) {
    const glm::dvec3 d = noisy.positions[i] - sphere.positions[i];
    ASSERT_LT(glm::length(glm::cross(d, normals[i])), 1e-12 * sigma) << "vertex " << i << " moved off its normal";
    const double along = glm::dot(d, normals[i]);
    sumMagnitude += std::abs(along);
    sumSigned += along;
    sumSquares += along * along;
  }
  const double n = double(sphere.positions.size());
  // E|X| = sigma sqrt(2/pi) for X ~ N(0, sigma^2); with 2562 samples the
  // estimate is within 2% (one standard error), so 10% is a wide margin.
  EXPECT_NEAR(sumMagnitude / n, sigma * std::sqrt(2.0 / std::numbers::pi),
              0.10 * sigma * std::sqrt(2.0 / std::numbers::pi));
  EXPECT_NEAR(std::sqrt(sumSquares / n), sigma, 0.10 * sigma);
  EXPECT_NEAR(sumSigned / n, 0.0, 0.10 * sigma) << "as often outwards as inwards";
}

TEST(Noise, ZeroSigmaChangesNothing)
{
  const TriangleMesh sphere = testing::icosphere(2);
  EXPECT_EQ(addNormalNoise(sphere, 0.0, 1).positions, sphere.positions);
}

// A soup (each triangle its own three corners, as STL stores it): the
// copies of a corner move as one, so the noisy soup is the noisy mesh's,
// whole. They moved apart, by two sigmas at the median.
TEST(Noise, ASoupsCopiesOfACornerMoveTogether)
{
  const TriangleMesh sphere = testing::icosphere(3);
  TriangleMesh soup;
  for (const glm::uvec3& t : sphere.triangles) {
    const uint32_t first = uint32_t(soup.positions.size());
    for (int k = 0; k < 3; ++k) soup.positions.push_back(sphere.positions[t[k]]);
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  const TriangleMesh noisySoup = addNormalNoise(soup, 0.3, 7);
  std::map<std::tuple<double, double, double>, glm::dvec3> movedTo;  // each corner's first copy
  size_t moved = 0;
  for (size_t i = 0; i < soup.positions.size(); ++i) {
    const glm::dvec3& p = soup.positions[i];
    const auto [at, first] = movedTo.try_emplace({p.x, p.y, p.z}, noisySoup.positions[i]);
    if (!first) {
      EXPECT_EQ(noisySoup.positions[i], at->second) << "corner " << i;
    }
    moved += noisySoup.positions[i] != p;
  }
  EXPECT_GT(moved, soup.positions.size() / 2);  // it is noisy
  EXPECT_EQ(movedTo.size(), sphere.positions.size());
}

}  // namespace
}  // namespace lbmshape
