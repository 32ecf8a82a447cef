// Topology of small meshes whose answers are known by hand.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/core/error.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

using testing::tetrahedron;

TEST(MeshTopology, OpenSquareHasABoundaryAndNoGenus)
{
  TriangleMesh square;
  square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const MeshTopology t = analyzeTopology(square);
  EXPECT_EQ(t.vertices, 4u);
  EXPECT_EQ(t.triangles, 2u);
  EXPECT_EQ(t.edges, 5u);
  EXPECT_EQ(t.boundaryEdges, 4u);
  EXPECT_EQ(t.nonManifoldEdges, 0u);
  EXPECT_EQ(t.nonManifoldVertices, 0u);
  EXPECT_EQ(t.components, 1u);
  EXPECT_TRUE(t.consistentlyOriented);
  EXPECT_FALSE(t.closedManifold);
  EXPECT_EQ(t.eulerCharacteristic, 1);
  EXPECT_FALSE(t.genus.has_value());
  EXPECT_DOUBLE_EQ(t.area, 1.0);
  EXPECT_DOUBLE_EQ(t.signedVolume, 0.0);
}

TEST(MeshTopology, TetrahedronIsAClosedSphere)
{
  const MeshTopology t = analyzeTopology(tetrahedron());
  EXPECT_EQ(t.edges, 6u);
  EXPECT_EQ(t.boundaryEdges, 0u);
  EXPECT_TRUE(t.closedManifold);
  EXPECT_TRUE(t.consistentlyOriented);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  EXPECT_EQ(t.genus, 0);
  EXPECT_NEAR(t.signedVolume, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(t.area, 1.5 + std::sqrt(3.0) / 2.0, 1e-15);
}

TEST(MeshTopology, InwardTetrahedronHasNegativeVolume)
{
  TriangleMesh m = tetrahedron();
  for (auto& f : m.triangles) std::swap(f[1], f[2]);
  const MeshTopology t = analyzeTopology(m);
  EXPECT_TRUE(t.closedManifold);
  EXPECT_NEAR(t.signedVolume, -1.0 / 6.0, 1e-15);
}

TEST(MeshTopology, OneFlippedTriangleBreaksOrientation)
{
  TriangleMesh m = tetrahedron();
  std::swap(m.triangles[3][1], m.triangles[3][2]);
  const MeshTopology t = analyzeTopology(m);
  EXPECT_EQ(t.inconsistentEdges, 3u);
  EXPECT_FALSE(t.consistentlyOriented);
  EXPECT_FALSE(t.closedManifold);
  EXPECT_FALSE(t.genus.has_value());
  EXPECT_EQ(t.boundaryEdges, 0u);
}

TEST(MeshTopology, TetrahedraSharingAnEdgeMakeItNonManifold)
{
  // The second tetrahedron reuses the first one's edge 0-1 (a book of four pages).
  TriangleMesh m = tetrahedron();
  m.positions.push_back({0, -1, 0});
  m.positions.push_back({0, 0, -1});
  m.triangles.insert(m.triangles.end(), {{0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}});
  const MeshTopology t = analyzeTopology(m);
  EXPECT_EQ(t.edges, 11u);
  EXPECT_EQ(t.nonManifoldEdges, 1u);
  EXPECT_EQ(t.boundaryEdges, 0u);
  EXPECT_EQ(t.components, 1u);
  EXPECT_FALSE(t.closedManifold);
  EXPECT_FALSE(t.genus.has_value());
}

TEST(MeshTopology, TetrahedraSharingAVertexMakeItNonManifold)
{
  TriangleMesh m = tetrahedron();
  // The tetrahedron reflected through its vertex 0 (which turns it inside
  // out, so its triangles are turned back), sharing only that vertex.
  TriangleMesh other = testing::scaled(tetrahedron(), -1.0);
  for (auto& f : other.triangles) std::swap(f[1], f[2]);
  other.positions.erase(other.positions.begin());
  for (auto& f : other.triangles)
    for (int k = 0; k < 3; ++k) f[k] = f[k] == 0 ? 0 : f[k] + 3;
  m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
  m.triangles.insert(m.triangles.end(), other.triangles.begin(), other.triangles.end());
  const MeshTopology t = analyzeTopology(m);
  EXPECT_EQ(t.vertices, 7u);
  EXPECT_EQ(t.nonManifoldVertices, 1u);
  EXPECT_EQ(t.nonManifoldEdges, 0u);
  EXPECT_EQ(t.boundaryEdges, 0u);
  EXPECT_TRUE(t.consistentlyOriented);
  EXPECT_EQ(t.components, 1u);
  EXPECT_FALSE(t.closedManifold);
  EXPECT_NEAR(t.signedVolume, 2.0 / 6.0, 1e-15);
}

TEST(MeshTopology, SeparatePartsAddTheirGenera)
{
  const TriangleMesh torus = testing::torusMesh(3.0, 1.0, 24, 12);
  const MeshTopology one = analyzeTopology(torus);
  EXPECT_TRUE(one.closedManifold);
  EXPECT_EQ(one.eulerCharacteristic, 0);
  EXPECT_EQ(one.genus, 1);
  EXPECT_GT(one.signedVolume, 0.0);

  const TriangleMesh parts = testing::merged(testing::merged(torus, testing::scaled(torus, 0.5)),
                                             testing::icosphere(2, 0.5, glm::dvec3(10, 0, 0)));
  const MeshTopology three = analyzeTopology(parts);
  EXPECT_TRUE(three.closedManifold);
  EXPECT_EQ(three.components, 3u);
  EXPECT_EQ(three.eulerCharacteristic, 2);
  EXPECT_EQ(three.genus, 2);
}

TEST(MeshTopology, SphereAreaAndVolumeApproachTheAnalyticValues)
{
  const MeshTopology t = analyzeTopology(testing::icosphere(5, 2.0, glm::dvec3(1e6, -2e6, 3e6)));
  EXPECT_TRUE(t.closedManifold);
  EXPECT_EQ(t.genus, 0);
  EXPECT_NEAR(t.area, 4 * std::numbers::pi * 4.0, 0.01 * 16 * std::numbers::pi);
  // Far from the origin the volume keeps its digits.
  EXPECT_NEAR(t.signedVolume, 4.0 / 3.0 * std::numbers::pi * 8.0, 0.01 * 32.0 / 3.0 * std::numbers::pi);
}

TEST(MeshTopology, DegenerateTrianglesAndUnusedVerticesAreCounted)
{
  TriangleMesh m = tetrahedron();
  m.positions.push_back({5, 5, 5});  // unreferenced
  m.triangles.push_back({1, 1, 2});  // repeated index
  const MeshTopology t = analyzeTopology(m);
  EXPECT_EQ(t.unreferencedVertices, 1u);
  EXPECT_EQ(t.degenerateTriangles, 1u);
  EXPECT_EQ(t.edges, 6u);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  EXPECT_EQ(t.components, 1u);
  EXPECT_FALSE(t.closedManifold);
}

TEST(MeshTopology, EmptyMeshIsNotClosed)
{
  const MeshTopology t = analyzeTopology(TriangleMesh{});
  EXPECT_EQ(t.triangles, 0u);
  EXPECT_EQ(t.components, 0u);
  EXPECT_FALSE(t.closedManifold);
  EXPECT_FALSE(t.genus.has_value());
}

TEST(MeshTopology, RejectsIndicesPastTheVertices)
{
  TriangleMesh m = tetrahedron();
  m.triangles.push_back({0, 1, 4});
  EXPECT_THROW(analyzeTopology(m), InputError);
}

}  // namespace
}  // namespace lbmshape
