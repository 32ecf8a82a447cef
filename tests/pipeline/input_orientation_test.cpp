// A denoise of a malformed export gives the shape it was meant to be: a
// sphere with part of its triangles wound the other way, or inside out, is
// smoothed as the clean sphere is; one part inside out of two is kept.
#include <random>

#include <gtest/gtest.h>

#include "analysis/mesh_topology.hpp"
#include "pipeline/denoise.hpp"
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
