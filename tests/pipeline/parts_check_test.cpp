// The parts a closed mesh's solid has: components that reach into one
// another are one solid (the winding number's union), a cavity is a part
// of its own; and the warning that a grid lost parts holds a result to that.
#include <algorithm>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/pipeline/parts_check.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

TriangleMesh turnedInside(TriangleMesh mesh)
{
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

TEST(SolidParts, OverlappingComponentsAreOneSolidACavityItsOwnPart)
{
  const TriangleMesh sphere = testing::icosphere(3);
  EXPECT_EQ(solidParts(sphere), 1u);
  EXPECT_EQ(solidParts(testing::merged(sphere, testing::icosphere(3, 1.0, {0.8, 0.0, 0.0}))), 1u) << "overlapping";
  EXPECT_EQ(solidParts(testing::merged(sphere, testing::icosphere(3, 1.0, {2.5, 0.0, 0.0}))), 2u) << "apart";
  EXPECT_EQ(solidParts(testing::merged(sphere, testing::icosphere(3, 0.3, {0.0, 0.0, 0.0}))), 1u)
      << "a solid inside a solid";
  EXPECT_EQ(solidParts(testing::merged(sphere, turnedInside(testing::icosphere(3, 0.3)))), 2u) << "a cavity";
  // Bounds that overlap, solids that do not: a post through a ring.
  const TriangleMesh ring = testing::torusMesh(1.0, 0.2, 48, 16);
  const TriangleMesh post = testing::scaled(testing::icosphere(3), 0.5);
  EXPECT_EQ(solidParts(testing::merged(ring, post)), 2u) << "a post through a ring, not touching it";
  // Three in a chain: a overlaps b, b overlaps c.
  EXPECT_EQ(solidParts(testing::merged(testing::merged(sphere, testing::icosphere(3, 1.0, {1.5, 0.0, 0.0})),
                                       testing::icosphere(3, 1.0, {3.0, 0.0, 0.0}))),
            1u);
}

TEST(PartsCheck, ARunHeldToTheUnionOfOverlappingPartsWarnsOnlyOfOtherLosses)
{
  const TriangleMesh overlapping = testing::merged(testing::icosphere(3), testing::icosphere(3, 1.0, {0.8, 0.0, 0.0}));
  const MeshTopology wanted = analyzeTopology(overlapping);
  ASSERT_EQ(wanted.components, 2u);
  MeshTopology united = analyzeTopology(testing::icosphere(3));  // what a grid makes of them: one part
  const log::WarningCollector quiet;
  warnIfThePartsChanged(overlapping, wanted, "the input", united, "the result", 0.05);
  EXPECT_TRUE(quiet.warnings().empty()) << "their union is one part";

  const TriangleMesh apart = testing::merged(testing::icosphere(3), testing::icosphere(3, 1.0, {2.5, 0.0, 0.0}));
  const log::WarningCollector warned;
  warnIfThePartsChanged(apart, analyzeTopology(apart), "the input", united, "the result", 0.05);
  ASSERT_EQ(warned.warnings().size(), 1u);
  EXPECT_NE(warned.warnings()[0].find("the result has 1 part of genus 0 where the input has 2 parts"),
            std::string::npos)
      << warned.warnings()[0];
}

}  // namespace
}  // namespace lbmshape
