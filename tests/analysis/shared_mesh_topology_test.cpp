// analyzeTopology on every shared test mesh agrees with the counts that
// ../shared/assets/README.md lists (made by its own checker, meshtool.py).
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "support/shared_assets.hpp"

namespace lbmshape {
namespace {

struct Expected {
  std::string file;
  size_t vertices, faces;
  std::optional<int64_t> genus;  // none for the open scan
  size_t boundaryEdges, nonManifoldEdges;
};

void PrintTo(const Expected& e, std::ostream* os) { *os << e.file; }

class SharedMeshTopology : public ::testing::TestWithParam<Expected> {};

TEST_P(SharedMeshTopology, MatchesTheReadme)
{
  const Expected& expected = GetParam();
  LBMSHAPE_REQUIRE_SHARED_ASSET(path, expected.file);
  const MeshTopology t = analyzeTopology(readMesh(path));
  EXPECT_EQ(t.vertices, expected.vertices);
  EXPECT_EQ(t.triangles, expected.faces);
  EXPECT_EQ(t.boundaryEdges, expected.boundaryEdges);
  EXPECT_EQ(t.nonManifoldEdges, expected.nonManifoldEdges);
  EXPECT_EQ(t.genus, expected.genus);
  EXPECT_EQ(t.closedManifold, expected.genus.has_value());
  EXPECT_EQ(t.unreferencedVertices, 0u);
  EXPECT_EQ(t.degenerateTriangles, 0u);
  if (t.closedManifold) {
    EXPECT_EQ(t.components, 1u);
    EXPECT_EQ(t.nonManifoldVertices, 0u);
    EXPECT_TRUE(t.consistentlyOriented);
    EXPECT_GT(t.signedVolume, 0.0) << "the README says every closed mesh faces outward";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Readme, SharedMeshTopology,
    ::testing::Values(Expected{"bunny.obj", 29834, 59664, 0, 0, 0},
                      Expected{"bunny_scan.obj", 34834, 69451, std::nullopt, 223, 0},
                      Expected{"armadillo.obj", 43243, 86482, 0, 0, 0}, Expected{"horse.obj", 48485, 96966, 0, 0, 0},
                      Expected{"spot.obj", 11533, 23062, 0, 0, 0}, Expected{"fandisk.obj", 6475, 12946, 0, 0, 0},
                      Expected{"rocker_arm.obj", 10044, 20088, 1, 0, 0}, Expected{"kitten.obj", 14472, 28944, 1, 0, 0},
                      Expected{"knot.obj", 3200, 6400, 1, 0, 0}, Expected{"eight.obj", 315, 634, 2, 0, 0},
                      Expected{"fertility.obj", 4494, 9000, 4, 0, 0}, Expected{"igea.obj", 134345, 268686, 0, 0, 0}),
    [](const ::testing::TestParamInfo<Expected>& info) {
      return info.param.file.substr(0, info.param.file.find('.'));
    });

}  // namespace
}  // namespace lbmshape
