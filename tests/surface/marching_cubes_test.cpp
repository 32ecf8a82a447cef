// Marching cubes on analytic fields (exact area, volume, genus and normals
// known) and on random fields (only the guarantees: closed, manifold,
// outward, no degenerate triangles, the same for any thread count).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <omp.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/core/error.hpp"
#include "support/implicit_fields.hpp"
#include "support/test_meshes.hpp"
#include "lbmshape/surface/marching_cubes.hpp"

namespace lbmshape {
namespace {

using testing::cubicFrame;
using testing::sampleImplicit;

constexpr double pi = std::numbers::pi;

TriangleMesh extract(const GridFrame& frame, const testing::ImplicitFunction& f, float iso = 0.0f)
{
  return extractSurface(sampleImplicit(frame, f), frame, iso);
}

// The guarantees of extractSurface for a level set inside the grid.
void expectClosedOutward(const TriangleMesh& mesh, const MeshTopology& topology)
{
  EXPECT_GT(topology.triangles, 0u);
  EXPECT_TRUE(topology.closedManifold);
  EXPECT_EQ(topology.boundaryEdges, 0u);
  EXPECT_EQ(topology.nonManifoldEdges, 0u);
  EXPECT_EQ(topology.nonManifoldVertices, 0u);
  EXPECT_EQ(topology.inconsistentEdges, 0u);
  EXPECT_EQ(topology.degenerateTriangles, 0u);
  EXPECT_EQ(topology.unreferencedVertices, 0u);
  EXPECT_GT(topology.signedVolume, 0.0);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    ASSERT_TRUE(std::isfinite(mesh.positions[i].x) && std::isfinite(mesh.positions[i].y) &&
                std::isfinite(mesh.positions[i].z));
    ASSERT_NEAR(glm::length(mesh.normals[i]), 1.0f, 1e-5f);
  }
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    ASSERT_GT(glm::length(glm::cross(b - a, c - a)), 0.0) << "zero-area triangle";
  }
}

double angleDegrees(const glm::dvec3& a, const glm::dvec3& b)
{
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

TEST(MarchingCubes, SphereIsClosedOutwardAndMatchesTheAnalyticSphere)
{
  const GridFrame frame = cubicFrame({64, 64, 64});
  const glm::dvec3 centre(31.7, 32.2, 31.9);
  const double R = 22.0;
  const TriangleMesh mesh = extract(frame, [&](const glm::dvec3& p) { return testing::sphereSdf(p, centre, R); });
  const MeshTopology topology = analyzeTopology(mesh);
  expectClosedOutward(mesh, topology);
  EXPECT_EQ(topology.components, 1u);
  EXPECT_EQ(topology.genus, 0);
  EXPECT_NEAR(topology.area, 4 * pi * R * R, 0.02 * 4 * pi * R * R);
  EXPECT_NEAR(topology.signedVolume, 4.0 / 3.0 * pi * R * R * R, 0.02 * 4.0 / 3.0 * pi * R * R * R);

  double worstRadius = 0, worstVertexNormal = 0, worstFaceNormal = 0;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::dvec3 radial = mesh.positions[i] - centre;
    worstRadius = std::max(worstRadius, std::abs(glm::length(radial) - R));
    worstVertexNormal = std::max(worstVertexNormal, angleDegrees(glm::dvec3(mesh.normals[i]), radial));
  }
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    worstFaceNormal = std::max(worstFaceNormal, angleDegrees(glm::cross(b - a, c - a), (a + b + c) / 3.0 - centre));
  }
  EXPECT_LT(worstRadius, 0.02);       // voxels
  EXPECT_LT(worstVertexNormal, 1.0);  // degrees: central differences of an exact distance
  EXPECT_LT(worstFaceNormal, 90.0);   // every triangle faces outward
}

TEST(MarchingCubes, LiesOnAFineSphereMesh)
{
  // Against an icosphere whose faces sag 0.003 voxels below the sphere.
  const GridFrame frame = cubicFrame({64, 64, 64});
  const glm::dvec3 centre(31.7, 32.2, 31.9);
  const double R = 22.0;
  const TriangleMesh mesh = extract(frame, [&](const glm::dvec3& p) { return testing::sphereSdf(p, centre, R); });
  ComparisonOptions options;
  options.minSamples = 50000;
  options.samplesPerTriangle = 2.0;
  const SurfaceComparison c = compareSurfaces(mesh, testing::icosphere(5, R, centre), options);
  // Triangles are chords: one spanning a cube diagonal (sqrt 3) sags 3 / 8R.
  EXPECT_LT(c.hausdorff, 0.03);  // voxels
  EXPECT_LT(c.mean, 0.01);
  EXPECT_LT(c.meanNormalAngle, 2.0);
}

TEST(MarchingCubes, WorldFrameScalesAndMovesTheSurface)
{
  // 0.05 units per voxel, the grid's first cell at (-1.6, -1.6, -1.6).
  const GridFrame frame = cubicFrame({64, 64, 64}, 0.05, glm::dvec3(-1.6));
  const glm::dvec3 centre(0.013, -0.021, 0.007);
  const double R = 1.1;
  const TriangleMesh mesh = extract(frame, [&](const glm::dvec3& p) { return testing::sphereSdf(p, centre, R); });
  const MeshTopology topology = analyzeTopology(mesh);
  expectClosedOutward(mesh, topology);
  EXPECT_NEAR(topology.area, 4 * pi * R * R, 0.02 * 4 * pi * R * R);
  for (const auto& p : mesh.positions) ASSERT_NEAR(glm::length(p - centre), R, 0.02 * frame.voxel);
}

TEST(MarchingCubes, IsovalueSelectsAnInnerLevelSet)
{
  const GridFrame frame = cubicFrame({64, 64, 64});
  const glm::dvec3 centre(32.3, 31.6, 32.1);
  const TriangleMesh mesh = extract(
      frame, [&](const glm::dvec3& p) { return testing::sphereSdf(p, centre, 25.0); }, 7.0f);
  expectClosedOutward(mesh, analyzeTopology(mesh));
  for (const auto& p : mesh.positions) ASSERT_NEAR(glm::length(p - centre), 18.0, 0.02);
}

TEST(MarchingCubes, TorusHasGenusOneAndTheAnalyticArea)
{
  const GridFrame frame = cubicFrame({64, 64, 64});
  const glm::dvec3 centre(31.6, 32.3, 31.8);
  const double R = 19.0, r = 7.5;
  const TriangleMesh mesh = extract(frame, [&](const glm::dvec3& p) { return testing::torusSdf(p, centre, R, r); });
  const MeshTopology topology = analyzeTopology(mesh);
  expectClosedOutward(mesh, topology);
  EXPECT_EQ(topology.components, 1u);
  EXPECT_EQ(topology.genus, 1);
  EXPECT_NEAR(topology.area, 4 * pi * pi * R * r, 0.02 * 4 * pi * pi * R * r);
  EXPECT_NEAR(topology.signedVolume, 2 * pi * pi * R * r * r, 0.02 * 2 * pi * pi * R * r * r);

  double worst = 0;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::dvec3 d = mesh.positions[i] - centre;
    const glm::dvec3 ring = glm::dvec3(glm::normalize(glm::dvec2(d)) * R, 0.0);
    worst = std::max(worst, angleDegrees(glm::dvec3(mesh.normals[i]), d - ring));
  }
  EXPECT_LT(worst, 2.0);
}

TEST(MarchingCubes, OverlappingSpheresMakeOneGenusZeroSurface)
{
  const GridFrame frame = cubicFrame({64, 64, 64});
  const double R = 14.0;
  // Far apart, barely overlapping (a neck about 2.6 voxels wide) and deep.
  for (double distance : {1.5 * R, 2.0 * R - 0.5}) {
    const glm::dvec3 a(31.8 - distance / 2, 32.1, 31.7), b(31.8 + distance / 2, 32.1, 31.7);
    const TriangleMesh mesh = extract(
        frame, [&](const glm::dvec3& p) { return std::max(testing::sphereSdf(p, a, R), testing::sphereSdf(p, b, R)); });
    const MeshTopology topology = analyzeTopology(mesh);
    expectClosedOutward(mesh, topology);
    EXPECT_EQ(topology.components, 1u) << "centres " << distance << " apart";
    EXPECT_EQ(topology.genus, 0) << "centres " << distance << " apart";
  }
}

TEST(MarchingCubes, TouchingSpheresStayManifold)
{
  // Two spheres that touch at a grid point and at a point between cells: the
  // field has a saddle there, where the table's face rule decides.
  const GridFrame frame = cubicFrame({64, 64, 64});
  const double R = 14.0;
  for (const glm::dvec3 contact : {glm::dvec3(32.0, 32.0, 32.0), glm::dvec3(31.5, 32.5, 31.5)}) {
    const glm::dvec3 a = contact - glm::dvec3(R, 0, 0), b = contact + glm::dvec3(R, 0, 0);
    const TriangleMesh mesh = extract(
        frame, [&](const glm::dvec3& p) { return std::max(testing::sphereSdf(p, a, R), testing::sphereSdf(p, b, R)); });
    const MeshTopology topology = analyzeTopology(mesh);
    expectClosedOutward(mesh, topology);
    EXPECT_LE(topology.components, 2u);
    EXPECT_EQ(topology.genus, 0);
  }
}

TEST(MarchingCubes, SeparateSpheresMakeTwoComponents)
{
  const GridFrame frame = cubicFrame({64, 64, 64});
  const double R = 12.0;
  const glm::dvec3 a(18.3, 31.6, 32.2), b(45.9, 32.4, 31.7);
  const TriangleMesh mesh = extract(
      frame, [&](const glm::dvec3& p) { return std::max(testing::sphereSdf(p, a, R), testing::sphereSdf(p, b, R)); });
  const MeshTopology topology = analyzeTopology(mesh);
  expectClosedOutward(mesh, topology);
  EXPECT_EQ(topology.components, 2u);
  EXPECT_EQ(topology.genus, 0);
  EXPECT_NEAR(topology.area, 2 * 4 * pi * R * R, 0.02 * 2 * 4 * pi * R * R);
}

// Random values in the interior, outside on the grid's outer layer.
Volume noise(Extent3 extent, uint32_t seed, std::vector<float> levels = {})
{
  Volume v(extent, -1.0f);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  std::uniform_int_distribution<size_t> pick(0, levels.empty() ? 0 : levels.size() - 1);
  for (int z = 1; z + 1 < extent.nz; ++z)
    for (int y = 1; y + 1 < extent.ny; ++y)
      for (int x = 1; x + 1 < extent.nx; ++x) v.at(x, y, z) = levels.empty() ? uniform(rng) : levels[pick(rng)];
  return v;
}

TEST(MarchingCubes, RandomFieldsGiveClosedManifolds)
{
  const Extent3 extent{24, 20, 28};
  for (uint32_t seed = 1; seed <= 8; ++seed) {
    const TriangleMesh mesh = extractSurface(noise(extent, seed), cubicFrame(extent));
    expectClosedOutward(mesh, analyzeTopology(mesh));
  }
}

TEST(MarchingCubes, SamplesEqualToTheIsovalueCountAsOutside)
{
  // Many samples exactly at the isovalue: no vertex on a grid point, no
  // zero-area triangle, and still closed.
  const Extent3 extent{20, 20, 20};
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    const Volume field = noise(extent, seed, {-1.0f, 0.0f, 0.0f, 1.0f});
    const TriangleMesh mesh = extractSurface(field, cubicFrame(extent));
    expectClosedOutward(mesh, analyzeTopology(mesh));
  }
  // A field that touches the isovalue without crossing it has no surface.
  Volume touching(extent, -1.0f);
  touching.at(10, 10, 10) = 0.0f;
  EXPECT_EQ(extractSurface(touching, cubicFrame(extent)).triangleCount(), 0u);
}

// Sets the corners of a block of cubes inside a grid whose other samples are
// outside, for every inside/outside pattern of the block's corners.
void expectEveryPatternClosed(int bx, int by, int bz)
{
  const Extent3 extent{bx + 3, by + 3, bz + 3};
  const int corners = (bx + 1) * (by + 1) * (bz + 1);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> magnitude(0.05f, 1.0f);
  for (uint32_t pattern = 1; pattern < (1u << corners); ++pattern) {
    Volume field(extent, -1.0f);
    for (int i = 0; i < corners; ++i) {
      const int x = i % (bx + 1), y = (i / (bx + 1)) % (by + 1), z = i / ((bx + 1) * (by + 1));
      field.at(x + 1, y + 1, z + 1) = ((pattern >> i) & 1 ? 1.0f : -1.0f) * magnitude(rng);
    }
    const TriangleMesh mesh = extractSurface(field, cubicFrame(extent));
    const MeshTopology topology = analyzeTopology(mesh);
    ASSERT_TRUE(topology.closedManifold) << "block " << bx << "x" << by << "x" << bz << ", pattern " << pattern;
    ASSERT_GT(topology.signedVolume, 0.0) << "block " << bx << "x" << by << "x" << bz << ", pattern " << pattern;
  }
}

TEST(MarchingCubes, EveryCubeCaseIsClosedAndOutward) { expectEveryPatternClosed(1, 1, 1); }

TEST(MarchingCubes, EveryPairOfCubesAgreesOnTheirSharedFace)
{
  expectEveryPatternClosed(2, 1, 1);
  expectEveryPatternClosed(1, 2, 1);
  expectEveryPatternClosed(1, 1, 2);
}

TEST(MarchingCubes, OutputDoesNotDependOnTheThreadCount)
{
  const Extent3 extent{40, 36, 44};
  const Volume field = noise(extent, 11);
  const GridFrame frame = cubicFrame(extent, 0.3, glm::dvec3(1.0, -2.0, 0.5));
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const TriangleMesh serial = extractSurface(field, frame);
  for (int n : {2, 3, 7}) {
    omp_set_num_threads(n);
    const TriangleMesh parallel = extractSurface(field, frame);
    EXPECT_EQ(parallel.positions, serial.positions) << n << " threads";
    EXPECT_EQ(parallel.normals, serial.normals) << n << " threads";
    EXPECT_EQ(parallel.triangles, serial.triangles) << n << " threads";
  }
  omp_set_num_threads(threads);
}

TEST(MarchingCubes, SurfaceLeavingTheGridIsOpenThere)
{
  // A slab through the whole grid: two open sheets, manifold inside.
  const GridFrame frame = cubicFrame({16, 16, 16});
  const TriangleMesh mesh = extract(frame, [](const glm::dvec3& p) { return 3.2 - std::abs(p.z - 7.6); });
  const MeshTopology topology = analyzeTopology(mesh);
  EXPECT_FALSE(topology.closedManifold);
  EXPECT_GT(topology.boundaryEdges, 0u);
  EXPECT_EQ(topology.nonManifoldEdges, 0u);
  EXPECT_EQ(topology.nonManifoldVertices, 0u);
  EXPECT_EQ(topology.inconsistentEdges, 0u);
  EXPECT_EQ(topology.components, 2u);
}

TEST(MarchingCubes, EmptyAndFlatFieldsGiveNoSurface)
{
  EXPECT_EQ(extractSurface(Volume({8, 8, 8}, -1.0f), cubicFrame({8, 8, 8})).triangleCount(), 0u);
  EXPECT_EQ(extractSurface(Volume({8, 8, 8}, 1.0f), cubicFrame({8, 8, 8})).triangleCount(), 0u);
  EXPECT_EQ(extractSurface(Volume({1, 8, 8}, 1.0f), cubicFrame({1, 8, 8})).triangleCount(), 0u);
}

TEST(MarchingCubes, RejectsBadInput)
{
  Volume field({8, 8, 8}, -1.0f);
  EXPECT_THROW(extractSurface(field, cubicFrame({8, 8, 9})), std::invalid_argument);
  EXPECT_THROW(extractSurface(field, cubicFrame({8, 8, 8}), std::nanf("")), UsageError);
  field.at(3, 4, 5) = std::nanf("");
  EXPECT_THROW(extractSurface(field, cubicFrame({8, 8, 8})), NumericalError);
  field.at(3, 4, 5) = INFINITY;
  EXPECT_THROW(extractSurface(field, cubicFrame({8, 8, 8})), NumericalError);
}

}  // namespace
}  // namespace lbmshape
