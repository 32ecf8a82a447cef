// glTF files from elsewhere: node transforms (TRS and matrix, nested),
// scenes, strips and fans, unindexed primitives, external buffers and GLB.
#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "mesh/hand_made_gltf.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;

glm::dvec3 minimum(const TriangleMesh& mesh) { return bounds(mesh).min; }
glm::dvec3 maximum(const TriangleMesh& mesh) { return bounds(mesh).max; }

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = 1e-6)
{
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

class GltfReading : public ::testing::TestWithParam<std::string> {
protected:
  // Writes the hand-made file as .gltf (+ .bin) or .glb, by the parameter.
  TriangleMesh readBack(const meshio::HandMadeGltf& gltf)
  {
    const auto path = folder_ / ("model" + GetParam());
    GetParam() == ".glb" ? gltf.writeGlb(path) : gltf.writeGltf(path);
    return readMesh(path);
  }

  testing::ScratchFolder folder_;
};

TEST_P(GltfReading, NodeTransformsAreAppliedThroughTheHierarchy)
{
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  gltf.json["nodes"] = {{{"translation", {10, 0, 0}}, {"children", {1}}},  // parent: move by +10 x
                        {{"scale", {2, 3, 4}}, {"mesh", mesh}}};           // child: stretch
  gltf.json["scenes"] = {{{"nodes", {0}}}};
  gltf.json["scene"] = 0;
  const TriangleMesh read = readBack(gltf);
  ASSERT_EQ(read.triangleCount(), 4u);
  expectNear(minimum(read), {10, 0, 0});
  expectNear(maximum(read), {12, 3, 4});
  EXPECT_NEAR(meshio::signedVolume(read), 24.0 / 6.0, 1e-9);
}

TEST_P(GltfReading, RotationAndMatrixNodes)
{
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  const double s = std::sqrt(0.5);
  gltf.json["nodes"] = {{{"rotation", {0, 0, s, s}}, {"mesh", mesh}},  // 90 degrees about z: x -> y
                        {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}},
                         {"mesh", mesh}}};  // column-major: moves by (5, 6, 7)
  gltf.json["scenes"] = {{{"nodes", {0, 1}}}};
  const TriangleMesh read = readBack(gltf);
  ASSERT_EQ(read.triangleCount(), 8u);
  expectNear(read.positions[1], {0, 1, 0});  // rotated (1, 0, 0)
  expectNear(read.positions[4 + 3], {5, 6, 8});
}

TEST_P(GltfReading, MirroringNodesKeepFacesOutward)
{
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  gltf.json["nodes"] = {{{"scale", {-1, 1, 1}}, {"mesh", mesh}}};
  gltf.json["scenes"] = {{{"nodes", {0}}}};
  EXPECT_NEAR(meshio::signedVolume(readBack(gltf)), 1.0 / 6.0, 1e-9);
}

// A node scaled to nothing, and what hangs from it, is hidden (a morph.glb's
// frames but the first): left out, not read as a point of degenerate
// triangles (render warned of thousands).
TEST_P(GltfReading, NodesScaledToNothingAreHidden)
{
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  gltf.json["nodes"] = {{{"mesh", mesh}},
                        {{"mesh", mesh}, {"translation", {5, 0, 0}}, {"scale", {0, 0, 0}}, {"children", {2}}},
                        {{"mesh", mesh}, {"translation", {0, 5, 0}}}};
  gltf.json["scenes"] = {{{"nodes", {0, 1}}}};
  const TriangleMesh read = readBack(gltf);
  EXPECT_EQ(read.triangleCount(), 4u) << "the shown node alone";
  expectNear(maximum(read), {1, 1, 1});
}

TEST_P(GltfReading, OnlyTheDefaultSceneIsRead)
{
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  gltf.json["nodes"] = {{{"mesh", mesh}}, {{"mesh", mesh}, {"translation", {0, 0, 5}}}};
  gltf.json["scenes"] = {{{"nodes", {0}}}, {{"nodes", {1}}}};
  gltf.json["scene"] = 1;
  expectNear(minimum(readBack(gltf)), {0, 0, 5});
}

TEST_P(GltfReading, WithoutScenesEveryRootNodeIsRead)
{
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  gltf.json["nodes"] = {{{"mesh", mesh}, {"children", {2}}},
                        {{"mesh", mesh}, {"translation", {3, 0, 0}}},
                        {{"mesh", mesh}, {"translation", {0, 3, 0}}}};
  EXPECT_EQ(readBack(gltf).triangleCount(), 12u) << "two roots, one child: each instance once";
}

TEST_P(GltfReading, StripsFansUnindexedAndShortIndices)
{
  meshio::HandMadeGltf gltf;
  // Square pyramid: the base as a strip, the sides as a fan around the apex.
  const int corners = gltf.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 1}});
  const int strip = gltf.addMesh(corners, gltf.addIndices16({1, 0, 3, 2}), 5);
  const int fan = gltf.addMesh(corners, gltf.addIndices({4, 0, 1, 3, 2, 0}), 6);
  // And a tetrahedron without indices: every three positions a triangle.
  std::vector<glm::vec3> soup;
  for (uint32_t i : meshio::tetraIndices) soup.push_back(meshio::tetraCorners[i] + glm::vec3(5, 0, 0));
  const int unindexed = gltf.addMesh(gltf.addPositions(soup), -1, 4);
  gltf.json["nodes"] = {{{"mesh", strip}}, {{"mesh", fan}}, {{"mesh", unindexed}}};
  gltf.json["scenes"] = {{{"nodes", {0, 1, 2}}}};
  const TriangleMesh read = readBack(gltf);
  EXPECT_EQ(read.triangleCount(), 2u + 4u + 4u);
  EXPECT_NEAR(meshio::signedVolume(read), 1.0 / 3.0 + 1.0 / 6.0, 1e-9) << "strip and fan windings followed";
}

// A required extension that changes nothing lbmshape reads (a material's)
// is read past; one it does not know may change the geometry, so, as the
// glTF specification asks of a reader, the file is refused, naming it.
TEST_P(GltfReading, AnUnknownRequiredExtensionIsRefusedNamingIt)
{
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  gltf.json["nodes"] = {{{"mesh", mesh}}};
  gltf.json["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  gltf.json["extensionsRequired"] = {"KHR_materials_emissive_strength"};
  EXPECT_EQ(readBack(gltf).triangleCount(), 4u);
  gltf.json["extensionsUsed"] = {"FOO_bent_space"};
  gltf.json["extensionsRequired"] = {"FOO_bent_space"};
  try {
    readBack(gltf);
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("requires the extension 'FOO_bent_space'"), std::string::npos) << e.what();
  }
}

// Primitives passed over (a CAD export's edge lines, one per part) are
// warned of once for each kind, with their count, not a line each.
TEST_P(GltfReading, SkippedPrimitivesAreWarnedOfOnce)
{
  meshio::HandMadeGltf gltf;
  const int positions = gltf.addPositions(meshio::tetraCorners), indices = gltf.addIndices(meshio::tetraIndices);
  const int tetra = gltf.addMesh(positions, indices);
  const int lines = gltf.addMesh(positions, indices, 1);
  for (int k = 0; k < 4; ++k)
    gltf.json["meshes"][lines]["primitives"].push_back({{"attributes", {{"POSITION", positions}}}, {"mode", 1}});
  gltf.json["nodes"] = {{{"mesh", tetra}}, {{"mesh", lines}}};
  gltf.json["scenes"] = {{{"nodes", {0, 1}}}};
  std::vector<std::string> warnings;
  log::setSink([&](log::Kind kind, const std::string& message) {
    if (kind == log::Kind::Warning) warnings.push_back(message);
  });
  const TriangleMesh read = readBack(gltf);
  log::setSink({});
  EXPECT_EQ(read.triangleCount(), 4u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("skipped 5 primitives (mesh 1 primitive 0 the first): points or lines"), std::string::npos)
      << warnings[0];
}

// A GLB saved under a .gltf name is read as the GLB it is, with a warning
// (its JSON parse failed: "last read: 'g'").
TEST(GltfReadingNamed, AGlbNamedGltfIsReadAsGlb)
{
  testing::ScratchFolder folder;
  meshio::HandMadeGltf gltf;
  gltf.json["nodes"] = {
      {{"mesh", gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices))}}};
  gltf.writeGlb(folder / "model.glb");
  std::filesystem::rename(folder / "model.glb", folder / "model.gltf");
  EXPECT_EQ(readMesh(folder / "model.gltf").triangleCount(), 4u);
}

// A skinned mesh is posed by its joints, as a viewer shows it without an
// animation, and the transform of the node that holds it is ignored (glTF
// 2.0, 3.7.3). Before, the skin was ignored and the node's translation
// applied: the mesh came out in its bind pose, 100 units off.
class GltfSkin : public GltfReading {
protected:
  // A tetrahedron held by node 0 (translated by 100, which must not count),
  // skinned to joints 1 and 2; joint 2 raised by 3 along z. Corners 0-2
  // follow joint 1 alone; corner 3 the two joints half and half.
  meshio::HandMadeGltf skinned(const glm::vec3& jointScale = glm::vec3(1.0f))
  {
    meshio::HandMadeGltf gltf;
    const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
    auto& attributes = gltf.json["meshes"][mesh]["primitives"][0]["attributes"];
    attributes["JOINTS_0"] = gltf.addJoints({{0, 1, 0, 0}, {0, 1, 0, 0}, {0, 1, 0, 0}, {0, 1, 0, 0}});
    attributes["WEIGHTS_0"] = gltf.addWeights({{1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}, {0.5, 0.5, 0, 0}});
    gltf.json["skins"] = {
        {{"joints", {1, 2}}, {"inverseBindMatrices", gltf.addMatrices({glm::mat4(1.0f), glm::mat4(1.0f)})}}};
    gltf.json["nodes"] = {{{"mesh", mesh}, {"skin", 0}, {"translation", {100, 0, 0}}},
                          {{"children", {2}}, {"scale", {jointScale.x, jointScale.y, jointScale.z}}},
                          {{"translation", {0, 0, 3}}}};
    gltf.json["scenes"] = {{{"nodes", {0, 1}}}};
    return gltf;
  }
};

TEST_P(GltfSkin, AMeshIsPosedByItsJointsNotByItsNode)
{
  const TriangleMesh read = readBack(skinned());
  ASSERT_EQ(read.vertexCount(), 4u);
  for (int v = 0; v < 3; ++v) expectNear(read.positions[size_t(v)], glm::dvec3(meshio::tetraCorners[size_t(v)]), 1e-6);
  expectNear(read.positions[3], glm::dvec3(meshio::tetraCorners[3]) + glm::dvec3(0, 0, 1.5), 1e-6);
  EXPECT_GT(meshio::signedVolume(read), 0.0);
}

// Joints that mirror turn the faces, as a mirroring node does.
TEST_P(GltfSkin, MirroringJointsKeepTheFacesOutward)
{
  const TriangleMesh read = readBack(skinned(glm::vec3(-1.0f, 1.0f, 1.0f)));
  EXPECT_NEAR(read.positions[1].x, -1.0, 1e-6);  // corner 1, (1, 0, 0), mirrored
  EXPECT_GT(meshio::signedVolume(read), 0.0);
}

TEST_P(GltfSkin, AJointPastTheSkinsIsRefusedNamingIt)
{
  meshio::HandMadeGltf gltf = skinned();
  gltf.json["skins"][0]["joints"] = {1};
  try {
    readBack(gltf);
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("JOINTS_0 refers to joint 1, but skin 0 has 1"), std::string::npos)
        << e.what();
  }
}

// A joint's number is a whole number: a float accessor's 0.5 (or NaN) was
// truncated to joint 0, or cast beyond an integer's range.
TEST_P(GltfSkin, AJointThatIsNoWholeNumberIsRefused)
{
  meshio::HandMadeGltf gltf = skinned();
  auto& attributes = gltf.json["meshes"][0]["primitives"][0]["attributes"];
  attributes["JOINTS_0"] = attributes["WEIGHTS_0"];  // floats: corner 3's joints 0.5 and 0.5
  try {
    readBack(gltf);
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("JOINTS_0 holds 0.5"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("which is not a joint's number"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Containers, GltfSkin, ::testing::Values(".gltf", ".glb"),
                         [](const auto& info) { return info.param.substr(1); });

// A Draco file as exporters write it: the compressed primitive's accessors
// have no buffer view. It is refused for the extension it requires, not for
// the accessors tinygltf cannot read ("accessor[1] invalid bufferView").
TEST_P(GltfReading, ADracoFileIsRefusedForItsExtension)
{
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  gltf.json["nodes"] = {{{"mesh", mesh}}};
  for (auto& accessor : gltf.json["accessors"]) accessor.erase("bufferView");
  // And an element a Draco encoder might write oddly: the extension is what
  // the file is refused for, not that.
  gltf.json["accessors"][0]["byteOffset"] = "0";
  gltf.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"] = {
      {"bufferView", 0}, {"attributes", {{"POSITION", 0}}}};
  gltf.json["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  gltf.json["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  try {
    readBack(gltf);
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("it requires KHR_draco_mesh_compression, which lbmshape cannot decode"),
              std::string::npos)
        << e.what();
  }
}

TEST_P(GltfReading, IndexBeyondTheVerticesIsAnInputError)
{
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices({0, 2, 1, 0, 1, 9}));
  gltf.json["nodes"] = {{{"mesh", mesh}}};
  EXPECT_THROW(readBack(gltf), InputError);
}

INSTANTIATE_TEST_SUITE_P(Containers, GltfReading, ::testing::Values(".gltf", ".glb"),
                         [](const auto& info) { return info.param.substr(1); });

}  // namespace
}  // namespace lbmshape
