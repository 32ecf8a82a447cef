// Tangential relaxation of marching cubes' triangles: on analytic surfaces
// (where the surface and its normals are known) the slivers go, the
// triangles' normals come nearer the surface's and the vertices stay on it;
// on crafted fans, open edges stay and no triangle is turned over.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "support/implicit_fields.hpp"
#include "support/test_meshes.hpp"
#include "lbmshape/surface/marching_cubes.hpp"
#include "lbmshape/surface/triangle_relaxation.hpp"

namespace lbmshape {
namespace {

constexpr double degrees = 180.0 / std::numbers::pi;

using testing::smallestAngle;

double sliverFraction(const TriangleMesh& mesh)
{
  return double(testing::triangleCountWithAngleUnder(mesh, 10.0)) / double(mesh.triangleCount());
}

// The mean angle, in degrees, between each triangle's normal and the
// sphere's at the triangle's centre.
double meanFaceNormalError(const TriangleMesh& mesh, const glm::dvec3& centre)
{
  double sum = 0.0;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::dvec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
    const glm::dvec3 face = glm::normalize(glm::cross(b - a, c - a));
    const glm::dvec3 sphere = glm::normalize((a + b + c) / 3.0 - centre);
    sum += std::acos(std::clamp(glm::dot(face, sphere), -1.0, 1.0)) * degrees;
  }
  return sum / double(mesh.triangleCount());
}

double largestOffTheSphere(const TriangleMesh& mesh, const glm::dvec3& centre, double R)
{
  double largest = 0.0;
  for (const glm::dvec3& p : mesh.positions) largest = std::max(largest, std::abs(glm::length(p - centre) - R));
  return largest;
}

double meanVertexNormalError(const TriangleMesh& mesh, const glm::dvec3& centre)
{
  double sum = 0.0;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const glm::dvec3 sphere = glm::normalize(mesh.positions[v] - centre);
    sum += std::acos(std::clamp(glm::dot(glm::dvec3(mesh.normals[v]), sphere), -1.0, 1.0)) * degrees;
  }
  return sum / double(mesh.vertexCount());
}

TEST(TriangleRelaxation, EvensOutMarchingCubesSliversAndKeepsTheSphere)
{
  const glm::dvec3 centre(16.3, 15.8, 16.1);
  const double R = 11.7;
  const GridFrame frame = testing::cubicFrame({33, 33, 33});
  const TriangleMesh before = extractSurface(
      testing::sampleImplicit(frame, [&](const glm::dvec3& p) { return testing::sphereSdf(p, centre, R); }), frame);
  TriangleMesh after = before;
  const RelaxationSummary summary = relaxTriangles(after, defaultRelaxationRounds);

  EXPECT_EQ(after.triangles, before.triangles);  // only the positions move
  EXPECT_GT(summary.movedVertices, before.vertexCount() / 2);
  EXPECT_GT(sliverFraction(before), 0.03);
  EXPECT_LT(sliverFraction(after), 0.2 * sliverFraction(before));
  EXPECT_LT(meanFaceNormalError(after, centre), 0.9 * meanFaceNormalError(before, centre));
  // The vertices move along the surface: off it by no more than marching
  // cubes' own error and a thousandth of a voxel (the step along the
  // plane alone left them 0.013 voxel off).
  EXPECT_LT(largestOffTheSphere(after, centre, R), largestOffTheSphere(before, centre, R) + 0.001);
  // The normals turned with the triangles: no further from the sphere's.
  ASSERT_EQ(after.normals.size(), after.positions.size());
  EXPECT_LT(meanVertexNormalError(after, centre), meanVertexNormalError(before, centre) + 0.001);
  for (const glm::vec3& n : after.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
  const MeshTopology topology = analyzeTopology(after);
  EXPECT_TRUE(topology.closedManifold);
  EXPECT_EQ(topology.inconsistentEdges, 0u);
  EXPECT_EQ(topology.degenerateTriangles, 0u);
  EXPECT_NEAR(topology.signedVolume, analyzeTopology(before).signedVolume, 1e-3 * analyzeTopology(before).signedVolume);
}

TEST(TriangleRelaxation, NoRoundsChangeNothingAndFewerThanNoneOrANanAreAMistake)
{
  const GridFrame frame = testing::cubicFrame({17, 17, 17});
  const TriangleMesh before = extractSurface(
      testing::sampleImplicit(frame, [](const glm::dvec3& p) { return testing::sphereSdf(p, glm::dvec3(8.2), 5.3); }),
      frame);
  TriangleMesh after = before;
  EXPECT_EQ(relaxTriangles(after, 0).movedVertices, 0u);
  EXPECT_EQ(after.positions, before.positions);
  EXPECT_EQ(after.normals, before.normals);
  EXPECT_THROW(relaxTriangles(after, -1), std::invalid_argument);
  // A library caller's mesh with a coordinate that is not a number.
  after.positions[0].x = std::nan("");
  EXPECT_THROW(relaxTriangles(after, 1), std::invalid_argument);
}

// A flat sheet of n x n vertices, the inner ones pushed about within it.
TriangleMesh unevenSheet(int n)
{
  TriangleMesh sheet;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const bool inner = i > 0 && j > 0 && i < n - 1 && j < n - 1;
      const double dx = inner ? 0.3 * std::sin(1.7 * i + 2.3 * j) : 0.0;
      const double dy = inner ? 0.3 * std::cos(2.9 * i - 1.1 * j) : 0.0;
      sheet.positions.emplace_back(i + dx, j + dy, 0.0);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const auto at = [n](int x, int y) { return uint32_t(y * n + x); };
      sheet.triangles.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      sheet.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return sheet;
}

TEST(TriangleRelaxation, AnOpenEdgeStaysAndAFlatSheetStaysFlat)
{
  const int n = 8;
  const TriangleMesh before = unevenSheet(n);
  TriangleMesh after = before;
  relaxTriangles(after, 3);
  double smallestBefore = 180.0, smallestAfter = 180.0;
  for (const glm::uvec3& t : before.triangles) {
    smallestBefore = std::min(smallestBefore, smallestAngle(before, t));
    smallestAfter = std::min(smallestAfter, smallestAngle(after, t));
  }
  EXPECT_GT(smallestAfter, smallestBefore + 5.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const size_t v = size_t(j * n + i);
      EXPECT_EQ(after.positions[v].z, 0.0);
      if (i == 0 || j == 0 || i == n - 1 || j == n - 1) {
        EXPECT_EQ(after.positions[v], before.positions[v]) << i << " " << j;
      }
    }
  EXPECT_TRUE(after.normals.empty());  // none to turn
}

// A vertex just left of the edge from (0.1, -0.05) to (0.1, 0.05), whose
// other neighbours lie far to the right: half the way to their centre
// (39.84, 0) takes it across that edge.
TEST(TriangleRelaxation, AMoveThatWouldTurnATriangleOverIsNotMade)
{
  TriangleMesh fan;
  fan.positions = {{0.0, 0.0, 0.0},     {0.1, -0.05, 0.0}, {0.1, 0.05, 0.0},
                   {100.0, 100.0, 0.0}, {-1.0, 0.0, 0.0},  {100.0, -100.0, 0.0}};
  for (uint32_t k = 1; k <= 5; ++k) fan.triangles.emplace_back(0u, k, k % 5 + 1);
  // Unguarded, the move would turn the first triangle over.
  const glm::dvec3 centre =
      (fan.positions[1] + fan.positions[2] + fan.positions[3] + fan.positions[4] + fan.positions[5]) / 5.0;
  const glm::dvec3 unguarded = 0.5 * centre;
  const glm::dvec3 a = fan.positions[1], b = fan.positions[2];
  ASSERT_LT(glm::cross(a - unguarded, b - unguarded).z, 0.0);
  ASSERT_GT(glm::cross(a - fan.positions[0], b - fan.positions[0]).z, 0.0);

  TriangleMesh relaxed = fan;
  const RelaxationSummary summary = relaxTriangles(relaxed, 1);
  EXPECT_EQ(summary.keptVertices, 1u);
  EXPECT_EQ(summary.movedVertices, 0u);
  EXPECT_EQ(relaxed.positions, fan.positions);
}

}  // namespace
}  // namespace lbmshape
