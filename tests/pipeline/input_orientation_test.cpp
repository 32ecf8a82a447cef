// A denoise of a malformed export gives the shape it was meant to be: a
// sphere with part of its triangles wound the other way, or inside out, is
// smoothed as the clean sphere is; one part inside out of two is kept.
#include <random>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

TriangleMesh turnedOver(TriangleMesh mesh, double fraction)
{
  std::mt19937 random(5);
  std::bernoulli_distribution pick(fraction);
  for (auto& t : mesh.triangles)
    if (pick(random)) std::swap(t[1], t[2]);
  return mesh;
}

TEST(InputOrientation, AMalformedExportIsSmoothedAsTheCleanMeshIs)
{
  ComputeDevice device{"", true};
  DenoiseOptions o;
  o.grid.resolution = 32;
  const TriangleMesh sphere = testing::icosphere(3);
  const DenoiseResult clean = denoiseMesh(sphere, "the sphere", o, device);
  for (const double fraction : {0.3, 0.5, 1.0}) {
    const DenoiseResult turned = denoiseMesh(turnedOver(sphere, fraction), "the turned sphere", o, device);
    EXPECT_EQ(turned.mesh.triangles, clean.mesh.triangles) << fraction;
    EXPECT_EQ(turned.mesh.positions, clean.mesh.positions) << fraction;
  }
}

// Every triangle with corners of its own (an unwelded OBJ, a glTF split at
// its seams), and inside out: joined, turned, and smoothed as the clean
// sphere is, its volume kept as a closed mesh's.
TEST(InputOrientation, ASoupInsideOutIsJoinedAndTurned)
{
  ComputeDevice device{"", true};
  DenoiseOptions o;
  o.grid.resolution = 32;
  const TriangleMesh sphere = testing::icosphere(3);
  TriangleMesh soup;
  for (const auto& t : sphere.triangles) {
    const uint32_t first = uint32_t(soup.positions.size());
    for (const int k : {0, 2, 1}) soup.positions.push_back(sphere.positions[t[k]]);
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  const DenoiseResult clean = denoiseMesh(sphere, "the sphere", o, device);
  const DenoiseResult joined = denoiseMesh(soup, "the soup", o, device);
  ASSERT_EQ(joined.mesh.triangles, clean.mesh.triangles);
  for (size_t i = 0; i < clean.mesh.positions.size(); ++i)
    ASSERT_NEAR(glm::distance(joined.mesh.positions[i], clean.mesh.positions[i]), 0.0, 1e-9) << i;
  EXPECT_NEAR(joined.report["volume_change"].get<double>(), clean.report["volume_change"].get<double>(), 1e-9);
}

TEST(InputOrientation, OnePartInsideOutOfTwoIsKept)
{
  ComputeDevice device{"", true};
  DenoiseOptions o;
  o.grid.resolution = 40;
  const TriangleMesh assembly =
      testing::merged(testing::icosphere(3), turnedOver(testing::icosphere(3, 0.6, {2.5, 0.0, 0.0}), 1.0));
  const MeshTopology result = analyzeTopology(denoiseMesh(assembly, "the assembly", o, device).mesh);
  EXPECT_EQ(result.components, 2u);
  EXPECT_TRUE(result.closedManifold);
  EXPECT_GT(result.signedVolume, 4.0 + 0.8);  // both balls' (4.19 and 0.90), less their facets
}

}  // namespace
}  // namespace lbmshape
