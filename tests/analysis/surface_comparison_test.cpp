// Surface distances on pairs whose answers are known analytically.
#include <cmath>

#include <gtest/gtest.h>
#include <omp.h>

#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/analysis/surface_sampling.hpp"
#include "lbmshape/core/error.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

// The rectangle [0, width] x [0, 1] in the plane z = 0, facing +z.
TriangleMesh rectangle(double width)
{
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {width, 0, 0}, {width, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(SurfaceComparison, IdenticalMeshesAreZeroApart)
{
  const TriangleMesh sphere = testing::icosphere(3);
  const SurfaceComparison c = compareSurfaces(sphere, sphere);
  EXPECT_LT(c.hausdorff, 1e-12);
  EXPECT_LT(c.mean, 1e-14);
  EXPECT_LT(c.rms, 1e-14);
  EXPECT_LT(c.meanNormalAngle, 1e-4);
  EXPECT_EQ(c.aToB.samples, 100000u + sphere.vertexCount());
}

TEST(SurfaceComparison, ScaledSphereIsEpsilonRApart)
{
  // Each face of the larger sphere is its twin moved out by eps times its
  // distance from the centre, which is R within the faces' sagitta (1e-4 R).
  const double R = 2.0, eps = 0.01;
  const glm::dvec3 centre(0.3, -0.2, 0.1);
  const TriangleMesh inner = testing::icosphere(5, R, centre);
  const TriangleMesh outer = testing::scaled(inner, 1.0 + eps, centre);
  const SurfaceComparison c = compareSurfaces(inner, outer);
  EXPECT_NEAR(c.hausdorff, eps * R, 0.02 * eps * R);
  EXPECT_NEAR(c.mean, eps * R, 0.02 * eps * R);
  EXPECT_NEAR(c.rms, eps * R, 0.02 * eps * R);
  EXPECT_NEAR(c.aToB.mean, c.bToA.mean, 0.02 * eps * R);
  EXPECT_LT(c.meanNormalAngle, 0.5);  // parallel faces, save near edges
}

TEST(SurfaceComparison, OneSidedDistancesTellTheDirectionsApart)
{
  // A = [0,1] x [0,1] lies inside B = [0,2] x [0,1]. From A every point is on
  // B; from B the right half is |x - 1| away: mean 1/4, rms sqrt(1/6), max 1.
  const SurfaceComparison c = compareSurfaces(rectangle(1.0), rectangle(2.0));
  EXPECT_LT(c.aToB.max, 1e-12);
  EXPECT_LT(c.aToB.mean, 1e-12);
  EXPECT_DOUBLE_EQ(c.bToA.max, 1.0);  // at B's corners, which are samples
  EXPECT_DOUBLE_EQ(c.bToA.farthest.x, 2.0);
  EXPECT_NEAR(c.bToA.mean, 0.25, 0.005);
  EXPECT_NEAR(c.bToA.rms, std::sqrt(1.0 / 6.0), 0.005);
  EXPECT_DOUBLE_EQ(c.hausdorff, 1.0);
  EXPECT_NEAR(c.mean, 0.125, 0.003);
  EXPECT_NEAR(c.rms, std::sqrt(1.0 / 12.0), 0.003);
  EXPECT_LT(c.meanNormalAngle, 1e-4);

  // Swapping the meshes swaps the directions.
  const SurfaceComparison swapped = compareSurfaces(rectangle(2.0), rectangle(1.0));
  EXPECT_EQ(swapped.aToB.mean, c.bToA.mean);
  EXPECT_EQ(swapped.bToA.max, c.aToB.max);
}

TEST(SurfaceComparison, NormalAngleIsOrientedAndInDegrees)
{
  TriangleMesh flipped = rectangle(1.0);
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  EXPECT_NEAR(compareSurfaces(rectangle(1.0), flipped).meanNormalAngle, 180.0, 1e-4);

  // Tilted by 30 degrees about the x axis.
  TriangleMesh tilted = rectangle(1.0);
  const double a = glm::radians(30.0);
  for (auto& p : tilted.positions) p = glm::dvec3(p.x, p.y * std::cos(a), p.y * std::sin(a));
  const SurfaceComparison c = compareSurfaces(rectangle(1.0), tilted);
  EXPECT_NEAR(c.aToB.meanNormalAngle, 30.0, 1e-6);
  EXPECT_NEAR(c.bToA.meanNormalAngle, 30.0, 1e-6);
  // The far edge of the tilted square is sin 30 = 1/2 above the plane.
  EXPECT_NEAR(c.bToA.max, 0.5, 1e-12);
}

// With trees built beforehand (a morph's target's, built with winding
// numbers for its distances) the figures are the same to the bit.
TEST(SurfaceComparison, TreesBuiltBeforeGiveTheSameFigures)
{
  const TriangleMesh inner = testing::icosphere(3, 1.0), outer = testing::icosphere(2, 1.1, {0.05, 0.0, 0.0});
  const ComparisonOptions options{20000, 0.0, true};
  const SurfaceComparison plain = compareSurfaces(inner, outer, options);
  const TriangleBvh innerTree(inner), outerTree(outer, TriangleBvh::Queries::ClosestOnly);
  const SurfaceComparison withTrees = compareSurfaces(inner, innerTree, outer, outerTree, options);
  EXPECT_GT(plain.mean, 0.01);
  EXPECT_EQ(withTrees.mean, plain.mean);
  EXPECT_EQ(withTrees.hausdorff, plain.hausdorff);
  EXPECT_EQ(withTrees.aToB.rms, plain.aToB.rms);
  EXPECT_EQ(withTrees.bToA.meanNormalAngle, plain.bToA.meanNormalAngle);
}

TEST(SurfaceComparison, ResultDoesNotDependOnTheThreadCount)
{
  const TriangleMesh a = testing::torusMesh(3.0, 1.0, 40, 20);
  const TriangleMesh b = testing::scaled(testing::torusMesh(3.0, 1.1, 33, 17), 1.02);
  ComparisonOptions options;
  options.minSamples = 20000;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const SurfaceComparison serial = compareSurfaces(a, b, options);
  omp_set_num_threads(3);
  const SurfaceComparison parallel = compareSurfaces(a, b, options);
  omp_set_num_threads(threads);
  EXPECT_EQ(serial.aToB.mean, parallel.aToB.mean);
  EXPECT_EQ(serial.bToA.rms, parallel.bToA.rms);
  EXPECT_EQ(serial.hausdorff, parallel.hausdorff);
  EXPECT_EQ(serial.meanNormalAngle, parallel.meanNormalAngle);
}

TEST(SurfaceComparison, SampleCountFollowsTheOptions)
{
  const TriangleMesh sphere = testing::icosphere(4);  // 5120 triangles, 2562 vertices
  ComparisonOptions options;
  options.minSamples = 1000;
  options.samplesPerTriangle = 3.0;
  options.includeVertices = false;
  EXPECT_EQ(compareSurfaces(sphere, sphere, options).aToB.samples, 3u * 5120u);
  options.includeVertices = true;
  EXPECT_EQ(compareSurfaces(sphere, sphere, options).bToA.samples, 3u * 5120u + 2562u);
}

TEST(SurfaceComparison, RejectsSurfacesWithoutArea)
{
  TriangleMesh flat;
  flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.triangles = {{0, 1, 2}};
  EXPECT_THROW(compareSurfaces(rectangle(1.0), flat), InputError);
  EXPECT_THROW(compareSurfaces(TriangleMesh{}, rectangle(1.0)), InputError);
}

TEST(SurfaceSampling, SpreadsPointsByAreaInsideTheTriangles)
{
  // Triangles of area 1/2 and 3/2: a quarter and three quarters of the points.
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 5}, {3, 0, 5}, {0, 1, 5}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  const auto samples = sampleSurface(m, 40000, 42);
  size_t first = 0;
  double meanX = 0;
  for (const auto& s : samples) {
    first += s.triangle == 0;
    const glm::dvec3 p = s.point - m.positions[m.triangles[s.triangle][0]];
    const double width = s.triangle == 0 ? 1.0 : 3.0;
    ASSERT_GE(p.x, 0.0);
    ASSERT_GE(p.y, 0.0);
    ASSERT_LE(p.x / width + p.y, 1.0 + 1e-12);
    ASSERT_NEAR(p.z, 0.0, 1e-12);
    if (s.triangle == 0) meanX += p.x;
  }
  EXPECT_NEAR(double(first) / samples.size(), 0.25, 0.01);
  EXPECT_NEAR(meanX / first, 1.0 / 3.0, 0.01);  // the centroid
  EXPECT_EQ(sampleSurface(m, 100, 7)[50].point, sampleSurface(m, 100, 7)[50].point);
  EXPECT_NE(sampleSurface(m, 100, 7)[50].point, sampleSurface(m, 100, 8)[50].point);
}

}  // namespace
}  // namespace lbmshape
