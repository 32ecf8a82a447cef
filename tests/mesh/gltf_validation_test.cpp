// Every glTF file lbmshape writes passes the Khronos glTF-Validator with no
// error and no warning, and the morph animation shows exactly one frame at
// any time.
#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/gltf_animation.hpp"
#include "mesh/hand_made_gltf.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "support/test_meshes.hpp"
#include "support/gltf_validator.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;

class GltfOutput : public ::testing::TestWithParam<std::string> {
protected:
  std::filesystem::path path(const std::string& stem) const { return folder_ / (stem + GetParam()); }
  testing::ScratchFolder folder_;
};

TEST_P(GltfOutput, SingleMeshIsValid)
{
  writeMesh(testing::icosphere(2, 0.3, {1, 2, 3}), path("sphere"));
  const auto validation = testing::validateGltf(path("sphere"));
  EXPECT_TRUE(validation.passed()) << validation;
}

TEST_P(GltfOutput, MeshWithItsOwnNormalsAndAnUnusedVertexIsValid)
{
  TriangleMesh mesh = testing::box({-1, -1, -1}, {2, 3, 4});
  for (const auto& p : mesh.positions) mesh.normals.push_back(glm::vec3(p) * 5.0f);  // not unit: normalised on writing
  mesh.normals[2] = glm::vec3(0.0f);                                                 // unusable: replaced
  mesh.positions.push_back({100, 100, 100});                                         // used by no triangle
  mesh.normals.push_back(glm::vec3(0.0f));
  writeMesh(mesh, path("box"));
  const auto validation = testing::validateGltf(path("box"));
  EXPECT_TRUE(validation.passed()) << validation;
}

TEST_P(GltfOutput, AnimationIsValid)
{
  std::vector<TriangleMesh> frames;
  for (uint32_t i = 0; i < 6; ++i) frames.push_back(addNormalNoise(testing::icosphere(2), 0.05 * i, i));
  writeGltfAnimation(frames, 24.0, path("morph"));
  const auto validation = testing::validateGltf(path("morph"));
  EXPECT_TRUE(validation.passed()) << validation;
  // A still viewer, like lbmshape's own reader, sees frame 0 only: the
  // other nodes rest at scale 0, so their triangles collapse and are dropped.
  EXPECT_EQ(readMesh(path("morph")).triangleCount(), frames[0].triangleCount());
}

TEST_P(GltfOutput, OneFrameAnimationIsValid)
{
  writeGltfAnimation({testing::icosphere(1)}, 10.0, path("still"));
  const auto validation = testing::validateGltf(path("still"));
  EXPECT_TRUE(validation.passed()) << validation;
}

// A morph's frame may have no surface. glTF has no empty meshes, so such a
// file is one node without a mesh (and no buffer: glTF has no empty ones
// either); without EmptyMesh::Allowed it is refused.
TEST_P(GltfOutput, EmptyMeshIsValidOnlyWhereAllowed)
{
  EXPECT_THROW(writeMesh(TriangleMesh{}, path("refused")), OutputError);
  EXPECT_FALSE(std::filesystem::exists(path("refused")));
  writeMesh(TriangleMesh{}, path("empty"), EmptyMesh::Allowed);
  const auto validation = testing::validateGltf(path("empty"));
  EXPECT_TRUE(validation.passed()) << validation;
  EXPECT_THROW(readMesh(path("empty")), InputError) << "as input, a file of no surface is an error";
}

TEST_P(GltfOutput, AnimationWithAnEmptyFrameIsValid)
{
  writeGltfAnimation({testing::icosphere(1), TriangleMesh{}, testing::icosphere(1, 2.0)}, 10.0, path("gap"));
  const auto validation = testing::validateGltf(path("gap"));
  EXPECT_TRUE(validation.passed()) << validation;
}

INSTANTIATE_TEST_SUITE_P(Containers, GltfOutput, ::testing::Values(".gltf", ".glb"),
                         [](const auto& info) { return info.param.substr(1); });

TEST(GltfValidatorHarness, ReportsTheErrorsOfABrokenFile)
{
  // Without bounds on POSITION a glTF file is invalid: the harness must say so.
  testing::ScratchFolder folder;
  meshio::HandMadeGltf gltf;
  const int positions = gltf.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  gltf.json["accessors"][size_t(positions)].erase("min");
  gltf.json["nodes"] = {{{"mesh", gltf.addMesh(positions, -1)}}};
  gltf.writeGltf(folder / "broken.gltf");
  const auto validation = testing::validateGltf(folder / "broken.gltf");
  EXPECT_TRUE(validation.failure.empty()) << validation;
  EXPECT_GT(validation.errors, 0) << validation;
  EXPECT_FALSE(validation.passed());
}

TEST(GltfOutputContent, SingleMeshHasGeneratorBoundsAndUnitNormals)
{
  testing::ScratchFolder folder;
  writeMesh(testing::box({-1, 0, 2}, {3, 5, 7}), folder / "box.glb");
  const auto glb = meshio::readGlb(folder / "box.glb");
  EXPECT_EQ(glb.json["asset"]["generator"], std::string("lbmshape ") + LBMSHAPE_VERSION);
  ASSERT_EQ(glb.json["meshes"].size(), 1u);
  ASSERT_EQ(glb.json["nodes"].size(), 1u);
  const auto& primitive = glb.json["meshes"][0]["primitives"][0];
  const auto& position = glb.json["accessors"][primitive["attributes"]["POSITION"].get<size_t>()];
  EXPECT_EQ(position["min"], nlohmann::json({-1.0, 0.0, 2.0}));
  EXPECT_EQ(position["max"], nlohmann::json({3.0, 5.0, 7.0}));
  EXPECT_EQ(glb.json["accessors"][primitive["indices"].get<size_t>()]["componentType"], 5125) << "uint32 indices";
  const auto normals = glb.floats(primitive["attributes"]["NORMAL"].get<int>());
  ASSERT_EQ(normals.size(), 3u * 8u);
  for (size_t i = 0; i < normals.size(); i += 3)
    EXPECT_NEAR(std::sqrt(normals[i] * normals[i] + normals[i + 1] * normals[i + 1] + normals[i + 2] * normals[i + 2]),
                1.0, 1e-6);
}

// The scale node `node` has at time t, by the STEP sampler that animates it.
float scaleAt(const meshio::GlbContent& glb, size_t node, float t)
{
  for (const auto& channel : glb.json["animations"][0]["channels"]) {
    if (channel["target"]["node"] != node) continue;
    EXPECT_EQ(channel["target"]["path"], "scale");
    const auto& sampler = glb.json["animations"][0]["samplers"][channel["sampler"].get<size_t>()];
    EXPECT_EQ(sampler["interpolation"], "STEP");
    const auto times = glb.floats(sampler["input"].get<int>());
    const auto scales = glb.floats(sampler["output"].get<int>());
    size_t key = 0;  // before the first key glTF holds the first value
    while (key + 1 < times.size() && times[key + 1] <= t) ++key;
    EXPECT_EQ(scales[3 * key], scales[3 * key + 1]);
    EXPECT_EQ(scales[3 * key], scales[3 * key + 2]);
    return scales[3 * key];
  }
  ADD_FAILURE() << "no channel animates node " << node;
  return -1;
}

TEST(GltfOutputContent, AnimationShowsExactlyOneFrameAtATime)
{
  const size_t frameCount = 5;
  const double fps = 10.0;
  std::vector<TriangleMesh> frames;
  for (size_t i = 0; i < frameCount; ++i) frames.push_back(testing::icosphere(1, 1.0 + 0.1 * double(i)));
  testing::ScratchFolder folder;
  writeGltfAnimation(frames, fps, folder / "morph.glb");
  const auto glb = meshio::readGlb(folder / "morph.glb");
  ASSERT_EQ(glb.json["nodes"].size(), frameCount);
  ASSERT_EQ(glb.json["meshes"].size(), frameCount);
  ASSERT_EQ(glb.json["animations"].size(), 1u);
  ASSERT_EQ(glb.json["animations"][0]["channels"].size(), frameCount);

  float end = 0;
  for (const auto& sampler : glb.json["animations"][0]["samplers"])
    end = std::max(end, glb.json["accessors"][sampler["input"].get<size_t>()]["max"][0].get<float>());
  EXPECT_FLOAT_EQ(end, float(double(frameCount) / fps)) << "the animation lasts frames / fps";

  for (size_t step = 0; step < 4 * frameCount; ++step) {
    const float t = float((double(step) + 0.5) / (4.0 * fps));  // four samples inside every frame
    const size_t expected = std::min(size_t(t * fps), frameCount - 1);
    for (size_t node = 0; node < frameCount; ++node)
      EXPECT_EQ(scaleAt(glb, node, t), node == expected ? 1.0f : 0.0f) << "node " << node << " at t = " << t;
  }
  // At the very end the last frame is still the one shown.
  for (size_t node = 0; node < frameCount; ++node)
    EXPECT_EQ(scaleAt(glb, node, end), node + 1 == frameCount ? 1.0f : 0.0f);
}

}  // namespace
}  // namespace lbmshape
