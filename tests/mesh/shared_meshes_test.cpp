// The shared test meshes (../shared/assets) read with the counts and bounds
// their README lists; bunny_scan, which has holes, with all its faces.
#include <gtest/gtest.h>

#include "lbmshape/mesh/mesh_reader.hpp"
#include "support/shared_assets.hpp"

namespace lbmshape {
namespace {

struct SharedMesh {
  std::string file;
  size_t vertices, faces;
  glm::dvec3 min, max;
};

// Names the case in test listings (instead of a dump of its bytes).
void PrintTo(const SharedMesh& mesh, std::ostream* out) { *out << mesh.file; }

class SharedMeshes : public ::testing::TestWithParam<SharedMesh> {};

TEST_P(SharedMeshes, ReadWithTheCountsAndBoundsOfTheReadme)
{
  const SharedMesh& expected = GetParam();
  LBMSHAPE_REQUIRE_SHARED_ASSET(path, expected.file);
  const TriangleMesh mesh = readMesh(path);
  EXPECT_EQ(mesh.vertexCount(), expected.vertices);
  EXPECT_EQ(mesh.triangleCount(), expected.faces);
  // The README gives 6 or 7 significant digits.
  const Bounds box = bounds(mesh);
  const double tolerance = 1e-5 * box.diagonal();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(box.min[k], expected.min[k], tolerance) << "axis " << k;
    EXPECT_NEAR(box.max[k], expected.max[k], tolerance) << "axis " << k;
  }
}

// From ../shared/assets/README.md.
INSTANTIATE_TEST_SUITE_P(
    Readme, SharedMeshes,
    ::testing::Values(
        SharedMesh{"bunny.obj", 29834, 59664, {-0.770217, -0.768455, -0.597181}, {0.779508, 0.769938, 0.601387}},
        SharedMesh{"bunny_scan.obj", 34834, 69451, {-0.09469, 0.032987, -0.061874}, {0.061009, 0.187321, 0.0588}},
        SharedMesh{"armadillo.obj", 43243, 86482, {-0.435275, -0.573402, -0.379481}, {0.403342, 0.426549, 0.38333}},
        SharedMesh{"horse.obj", 48485, 96966, {-0.042003, -0.0916705, -0.076418}, {0.042003, 0.0916705, 0.076418}},
        SharedMesh{"spot.obj", 11533, 23062, {-0.463426, -0.730229, -0.699571}, {0.464191, 1.01738, 1.0776}},
        SharedMesh{"fandisk.obj", 6475, 12946, {0, 12.6055, -2.68026}, {4.8279, 17.85, 0}},
        SharedMesh{"rocker_arm.obj", 10044, 20088, {-0.151733, -0.257456, -0.5}, {0.151733, 0.257456, 0.5}},
        SharedMesh{"kitten.obj", 14472, 28944, {-0.32239, -0.494397, -0.292937}, {0.32239, 0.494397, 0.292937}},
        SharedMesh{"knot.obj", 3200, 6400, {-0.480101, -0.5, -0.232322}, {0.480101, 0.5, 0.232322}},
        SharedMesh{"eight.obj", 315, 634, {-0.243695, -0.103765, -0.499314}, {0.243695, 0.103828, 0.499314}},
        SharedMesh{"fertility.obj", 4494, 9000, {-75.6563, -76.5288, -36.815}, {123.535, 67.7828, 36.4514}},
        SharedMesh{"igea.obj", 134345, 268686, {-0.034556, -0.049669, -0.049538}, {0.034556, 0.049669, 0.049538}}),
    [](const auto& info) {
      std::string name = info.param.file.substr(0, info.param.file.find('.'));
      return name;
    });

}  // namespace
}  // namespace lbmshape
