// compareSurfaces on real meshes, closed and open: a copy moved by delta is
// at most delta away everywhere (each point p has p + delta on the copy), and
// about delta on average where the surface is not parallel to the move.
#include <string>

#include <gtest/gtest.h>

#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "support/shared_assets.hpp"

namespace lbmshape {
namespace {

class SharedMeshComparison : public ::testing::TestWithParam<std::string> {};

TEST_P(SharedMeshComparison, MovedCopyIsAtMostTheMoveAway)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(path, GetParam());
  const TriangleMesh mesh = readMesh(path);
  const double delta = 1e-3 * bounds(mesh).diagonal();
  TriangleMesh moved = mesh;
  for (auto& p : moved.positions) p += glm::dvec3(0.6, 0.0, 0.8) * delta;

  ComparisonOptions options;
  options.minSamples = 20000;
  options.samplesPerTriangle = 0.5;
  const SurfaceComparison c = compareSurfaces(mesh, moved, options);
  EXPECT_LE(c.hausdorff, delta * (1 + 1e-9));
  EXPECT_GT(c.hausdorff, 0.5 * delta);
  EXPECT_GT(c.mean, 0.1 * delta);
  EXPECT_LE(c.rms, delta);
  EXPECT_LT(c.meanNormalAngle, 5.0);
}

INSTANTIATE_TEST_SUITE_P(Shared, SharedMeshComparison,
                         ::testing::Values("bunny_scan.obj", "knot.obj", "fandisk.obj", "fertility.obj"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

}  // namespace
}  // namespace lbmshape
