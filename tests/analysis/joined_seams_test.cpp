// A mesh's seams joined as lbmshape reads it (analysis/joined_seams.hpp).
#include <gtest/gtest.h>

#include "lbmshape/analysis/joined_seams.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

// A sphere in two halves that number the equator's vertices each their own
// way, as a glTF with a primitive per material does: one closed surface.
TriangleMesh sphereInTwoPieces()
{
  TriangleMesh split = testing::upperHalf(testing::icosphere(3));
  const TriangleMesh lower = testing::lowerHalf(testing::icosphere(3));
  const auto offset = uint32_t(split.positions.size());
  split.positions.insert(split.positions.end(), lower.positions.begin(), lower.positions.end());
  for (const glm::uvec3& t : lower.triangles) split.triangles.push_back(t + offset);
  return split;
}

TEST(JoinedSeams, PiecesNumberedApartAreOneClosedSurface)
{
  const TriangleMesh split = sphereInTwoPieces();
  EXPECT_GT(analyzeTopology(split).boundaryEdges, 0u);
  const JoinedSeams seams = joinSeams(split);
  ASSERT_TRUE(seams.joined.has_value());
  EXPECT_TRUE(seams.topology.closedManifold);
  EXPECT_EQ(seams.topology.components, 1u);
  EXPECT_EQ(seams.topology.genus, 0);
  EXPECT_GT(seams.joinedVertices, 0u);
  EXPECT_EQ(seams.boundaryEdgesBefore, analyzeTopology(split).boundaryEdges);
  // Vertices no triangle uses are not counted as joined.
  TriangleMesh withUnused = split;
  for (int k = 0; k < 100; ++k) withUnused.positions.emplace_back(5.0 + k, 0.0, 0.0);
  EXPECT_EQ(joinSeams(withUnused).joinedVertices, seams.joinedVertices);
}

// An open mesh's own rim is no seam: nothing joins, and its topology is its own.
TEST(JoinedSeams, AnOpenMeshStaysAsItIs)
{
  const TriangleMesh half = testing::upperHalf(testing::icosphere(3));
  const JoinedSeams seams = joinSeams(half);
  EXPECT_FALSE(seams.joined.has_value());
  EXPECT_EQ(seams.joinedVertices, 0u);
  EXPECT_EQ(seams.topology.boundaryEdges, analyzeTopology(half).boundaryEdges);
  EXPECT_GT(seams.topology.boundaryEdges, 0u);
}

}  // namespace
}  // namespace lbmshape
