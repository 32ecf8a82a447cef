// --compress: the .glb files lbmshape writes with KHR_mesh_quantization and
// EXT_meshopt_compression, decoded here with meshoptimizer's own decoders
// (the glTF-Validator cannot decode them) and compared with the mesh that
// was written: same triangles, positions within half a quantization step,
// normals within a degree; and every file validator-clean.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>

#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/glb_container.hpp"
#include "lbmshape/mesh/gltf_animation.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "mesh/hand_made_gltf.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/gltf_validator.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;

// One bufferView's bytes, decoded as the extension says.
std::vector<unsigned char> decodeView(const meshio::GlbContent& glb, int view)
{
  const nlohmann::json& ext = glb.json["bufferViews"][view]["extensions"]["EXT_meshopt_compression"];
  EXPECT_EQ(ext["buffer"], 0);
  const size_t count = ext["count"], stride = ext["byteStride"], offset = ext.value("byteOffset", 0),
               length = ext["byteLength"];
  std::vector<unsigned char> out(count * stride);
  const unsigned char* encoded = glb.binary.data() + offset;
  const int status = ext["mode"] == "TRIANGLES"
                         ? meshopt_decodeIndexBuffer(out.data(), count, stride, encoded, length)
                         : meshopt_decodeVertexBuffer(out.data(), count, stride, encoded, length);
  EXPECT_EQ(status, 0);
  return out;
}

struct Decoded {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;
  std::vector<uint32_t> indices;
};

// The mesh of node `node`'s child, positions dequantized by the node's
// translation (the quantization's offset, on the node itself so that a
// hidden frame shrinks to its own place) and the child's scale (its step).
Decoded decodeMesh(const meshio::GlbContent& glb, int node)
{
  const nlohmann::json& parent = glb.json["nodes"][node];
  const nlohmann::json& child = glb.json["nodes"][parent["children"][0].get<int>()];
  EXPECT_FALSE(child.contains("translation"));
  const nlohmann::json& primitive = glb.json["meshes"][child["mesh"].get<int>()]["primitives"][0];
  const nlohmann::json& accessors = glb.json["accessors"];
  const nlohmann::json& position = accessors[primitive["attributes"]["POSITION"].get<int>()];
  const nlohmann::json& normal = accessors[primitive["attributes"]["NORMAL"].get<int>()];
  const nlohmann::json& index = accessors[primitive["indices"].get<int>()];
  EXPECT_EQ(position["componentType"], 5123);  // unsigned short
  EXPECT_EQ(normal["componentType"], 5120);    // byte
  EXPECT_TRUE(normal["normalized"].get<bool>());
  const glm::dvec3 translation(parent["translation"][0], parent["translation"][1], parent["translation"][2]);
  const double scale = child["scale"][0];
  EXPECT_EQ(child["scale"][1], scale);
  EXPECT_EQ(child["scale"][2], scale);

  Decoded d;
  const auto p = decodeView(glb, position["bufferView"]);
  const auto n = decodeView(glb, normal["bufferView"]);
  const auto i = decodeView(glb, index["bufferView"]);
  const size_t count = position["count"];
  for (size_t v = 0; v < count; ++v) {
    uint16_t q[4];
    std::memcpy(q, p.data() + 8 * v, 8);
    d.positions.push_back(translation + scale * glm::dvec3(q[0], q[1], q[2]));
    const auto* b = reinterpret_cast<const int8_t*>(n.data() + 4 * v);
    d.normals.push_back(glm::max(glm::dvec3(b[0], b[1], b[2]) / 127.0, glm::dvec3(-1.0)));
  }
  const size_t indexSize = index["componentType"] == 5123 ? 2 : 4;
  for (size_t k = 0; k < index["count"].get<size_t>(); ++k) {
    uint32_t value = 0;
    std::memcpy(&value, i.data() + indexSize * k, indexSize);
    d.indices.push_back(value);
  }
  return d;
}

// Triangles as sorted-rotation triples of original vertex indices.
std::vector<std::array<uint32_t, 3>> canonical(std::vector<std::array<uint32_t, 3>> triangles)
{
  for (auto& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

void expectSameMesh(const TriangleMesh& original, const Decoded& d, double step)
{
  // Each decoded vertex is the original vertex nearest to it.
  std::vector<uint32_t> originalOf(d.positions.size());
  const std::vector<glm::dvec3> normals = areaWeightedNormals(original);
  double worstPosition = 0.0, worstNormalDegrees = 0.0;
  for (size_t v = 0; v < d.positions.size(); ++v) {
    double best = INFINITY;
    for (size_t o = 0; o < original.vertexCount(); ++o) {
      const double distance = glm::length(original.positions[o] - d.positions[v]);
      if (distance < best) best = distance, originalOf[v] = uint32_t(o);
    }
    worstPosition = std::max(worstPosition, best);
    const double cosine = glm::dot(glm::normalize(d.normals[v]), normals[originalOf[v]]);
    worstNormalDegrees = std::max(worstNormalDegrees, std::acos(std::min(cosine, 1.0)) * 180.0 / M_PI);
  }
  EXPECT_LE(worstPosition, 0.5 * std::sqrt(3.0) * step * 1.0001);
  EXPECT_LT(worstNormalDegrees, 1.0);
  std::vector<std::array<uint32_t, 3>> decoded, expected;
  for (size_t k = 0; k + 2 < d.indices.size(); k += 3)
    decoded.push_back({originalOf[d.indices[k]], originalOf[d.indices[k + 1]], originalOf[d.indices[k + 2]]});
  for (const glm::uvec3& t : original.triangles) expected.push_back({t.x, t.y, t.z});
  EXPECT_EQ(canonical(decoded), canonical(expected)) << "the same triangles, wound the same way";
}

TEST(CompressedGltf, AMeshDecodesToTheSameTrianglesWithinHalfAStep)
{
  testing::ScratchFolder folder;
  const TriangleMesh sphere = testing::icosphere(4, 3.0, {10.0, -2.0, 5.0});
  writeMesh(sphere, folder / "sphere.glb", EmptyMesh::Refused, GltfCompression::Meshopt);
  const auto validation = testing::validateGltf(folder / "sphere.glb");
  EXPECT_TRUE(validation.passed()) << validation;
  const meshio::GlbContent glb = meshio::readGlb(folder / "sphere.glb");
  EXPECT_EQ(glb.json["extensionsRequired"], nlohmann::json({"EXT_meshopt_compression", "KHR_mesh_quantization"}));
  EXPECT_FALSE(glb.json["buffers"][1].contains("uri")) << "the fallback buffer is declared, not stored";
  EXPECT_TRUE(glb.json["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"].get<bool>());
  const double step = 6.0 / 65535.0;  // the sphere's extent over the 16-bit grid
  expectSameMesh(sphere, decodeMesh(glb, glb.json["scenes"][0]["nodes"][0]), step);
}

TEST(CompressedGltf, LargeMeshesUse32BitIndicesAndStaySmall)
{
  testing::ScratchFolder folder;
  const TriangleMesh sphere = testing::icosphere(7);  // 163842 vertices
  writeMesh(sphere, folder / "plain.glb");
  writeMesh(sphere, folder / "small.glb", EmptyMesh::Refused, GltfCompression::Meshopt);
  const meshio::GlbContent glb = meshio::readGlb(folder / "small.glb");
  const nlohmann::json& primitive = glb.json["meshes"][0]["primitives"][0];
  EXPECT_EQ(glb.json["accessors"][primitive["indices"].get<int>()]["componentType"], 5125);
  EXPECT_LT(std::filesystem::file_size(folder / "small.glb") * 4, std::filesystem::file_size(folder / "plain.glb"));
  const Decoded d = decodeMesh(glb, glb.json["scenes"][0]["nodes"][0]);
  EXPECT_EQ(d.indices.size(), 3 * sphere.triangleCount());
  EXPECT_EQ(d.positions.size(), sphere.vertexCount());
}

TEST(CompressedGltf, AnAnimationKeepsItsNodesAndDecodesEveryFrame)
{
  testing::ScratchFolder folder;
  std::vector<TriangleMesh> frames = {testing::icosphere(2, 1.0), TriangleMesh{}, testing::icosphere(2, 2.0)};
  writeGltfAnimation(frames, 24.0, folder / "morph.glb", GltfCompression::Meshopt);
  const auto validation = testing::validateGltf(folder / "morph.glb");
  EXPECT_TRUE(validation.passed()) << validation;
  const meshio::GlbContent glb = meshio::readGlb(folder / "morph.glb");
  const nlohmann::json& roots = glb.json["scenes"][0]["nodes"];
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_FALSE(glb.json["nodes"][roots[1].get<int>()].contains("mesh")) << "an empty frame is a node without a mesh";
  EXPECT_FALSE(glb.json["nodes"][roots[1].get<int>()].contains("children"));
  for (const auto& channel : glb.json["animations"][0]["channels"])
    EXPECT_NE(std::find(roots.begin(), roots.end(), channel["target"]["node"]), roots.end())
        << "animations scale the frames' own nodes";
  expectSameMesh(frames[2], decodeMesh(glb, roots[2]), 4.0 / 65535.0);
}

// A plain animation too stores each frame about its own centre (its
// node's translation): a hidden frame (scale 0) shrinks to a point within
// itself, not to the origin, which viewers framing the scene took in (a
// morph 10 units out was framed from 0 to 10.5). Shown, a frame is where it
// was.
TEST(PlainGltfAnimation, HiddenFramesShrinkWithinThemselves)
{
  testing::ScratchFolder folder;
  const glm::dvec3 far(10.0, 0.0, 0.0);
  std::vector<TriangleMesh> frames = {testing::icosphere(2, 1.0, far), testing::icosphere(2, 1.2, far)};
  writeGltfAnimation(frames, 24.0, folder / "morph.glb");
  const auto validation = testing::validateGltf(folder / "morph.glb");
  EXPECT_TRUE(validation.passed()) << validation;
  const meshio::GlbContent glb = meshio::readGlb(folder / "morph.glb");
  const nlohmann::json& roots = glb.json["scenes"][0]["nodes"];
  ASSERT_EQ(roots.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    const nlohmann::json& node = glb.json["nodes"][roots[k].get<int>()];
    ASSERT_TRUE(node.contains("translation")) << k;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(node["translation"][a].get<double>(), far[a], 1e-9) << k;
    const nlohmann::json& position =
        glb.json["accessors"]
                [glb.json["meshes"][node["mesh"].get<int>()]["primitives"][0]["attributes"]["POSITION"].get<int>()];
    EXPECT_NEAR(position["min"][0].get<double>(), -position["max"][0].get<double>(), 1e-6) << "about its centre";
  }
  const TriangleMesh back = readMesh(folder / "morph.glb");  // frame 0, the one shown at rest
  EXPECT_NEAR(bounds(back).centre().x, far.x, 1e-6);
}

TEST(CompressedGltf, AFileOfNoSurfaceIsThePlainOne)
{
  testing::ScratchFolder folder;
  writeMesh(TriangleMesh{}, folder / "empty.glb", EmptyMesh::Allowed, GltfCompression::Meshopt);
  const auto validation = testing::validateGltf(folder / "empty.glb");
  EXPECT_TRUE(validation.passed()) << validation;
  const meshio::GlbContent glb = meshio::readGlb(folder / "empty.glb");
  EXPECT_FALSE(glb.json.contains("extensionsRequired")) << "nothing was encoded";
  EXPECT_FALSE(glb.json.contains("buffers"));
}

TEST(CompressedGltf, OnlyGlbFilesAreCompressed)
{
  testing::ScratchFolder folder;
  for (const char* name : {"m.gltf", "m.obj", "m.ply"})
    EXPECT_THROW(writeMesh(testing::icosphere(1), folder / name, EmptyMesh::Refused, GltfCompression::Meshopt),
                 UsageError)
        << name;
  EXPECT_THROW(writeGltfAnimation({testing::icosphere(1)}, 24.0, folder / "m.gltf", GltfCompression::Meshopt),
               UsageError);
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace lbmshape

namespace lbmshape {
namespace {

// A compressed GLB of `mesh` whose JSON `change` edits (or whose binary
// chunk it corrupts), written to `path`.
void writeAltered(const TriangleMesh& mesh, const std::filesystem::path& path,
                  const std::function<void(nlohmann::json&, std::vector<unsigned char>&)>& change)
{
  writeMesh(mesh, path, EmptyMesh::Refused, GltfCompression::Meshopt);
  meshio::GlbContent glb = meshio::readGlb(path);
  change(glb.json, glb.binary);
  std::ofstream(path, std::ios::binary) << glbFile(glb.json.dump(), std::string(glb.binary.begin(), glb.binary.end()));
}

TEST(CompressedGltf, LbmshapeReadsWhatItCompressed)
{
  testing::ScratchFolder folder;
  const TriangleMesh sphere = testing::icosphere(4, 2.0, {1.0, 2.0, 3.0});
  writeMesh(sphere, folder / "sphere.glb", EmptyMesh::Refused, GltfCompression::Meshopt);
  const TriangleMesh read = readMesh(folder / "sphere.glb");
  ASSERT_EQ(read.triangleCount(), sphere.triangleCount());
  ASSERT_EQ(read.vertexCount(), sphere.vertexCount());
  const double step = 4.0 / 65535.0;
  double worst = 0.0;
  for (const glm::dvec3& p : read.positions) {
    double nearest = INFINITY;
    for (const glm::dvec3& q : sphere.positions) nearest = std::min(nearest, glm::length(p - q));
    worst = std::max(worst, nearest);
  }
  EXPECT_LE(worst, 0.5 * std::sqrt(3.0) * step * 1.0001);
  EXPECT_NEAR(meshio::signedVolume(read), meshio::signedVolume(sphere), 1e-3 * meshio::signedVolume(sphere));
}

// The same file saved as .gltf and .bin, as tools may: lbmshape decodes
// meshopt in GLB files only, and says so (it said "buffer 1 has no uri",
// or with the extension only used, nothing of meshopt).
TEST(CompressedGltf, InAGltfFileItIsRefusedForWhatItNeeds)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "sphere.glb", EmptyMesh::Refused, GltfCompression::Meshopt);
  meshio::GlbContent glb = meshio::readGlb(folder / "sphere.glb");
  glb.json["buffers"][0]["uri"] = "sphere.bin";
  std::ofstream(folder / "sphere.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(glb.binary.data()), std::streamsize(glb.binary.size()));
  const auto refusal = [&] {
    std::ofstream(folder / "sphere.gltf") << glb.json.dump();
    try {
      readMesh(folder / "sphere.gltf");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("read");
  };
  std::string message = refusal();
  EXPECT_NE(message.find("requires EXT_meshopt_compression, which lbmshape decodes in GLB files only"),
            std::string::npos)
      << message;
  glb.json["extensionsRequired"] = {"KHR_mesh_quantization"};
  message = refusal();
  EXPECT_NE(message.find("buffer 1 has no uri (EXT_meshopt_compression's fallback buffer?"), std::string::npos)
      << message;
}

struct BadCompression {
  const char* name;
  std::function<void(nlohmann::json&, std::vector<unsigned char>&)> change;
  const char* mentions;
};

void PrintTo(const BadCompression& c, std::ostream* os) { *os << c.name; }

class CompressedGltfRefused : public ::testing::TestWithParam<BadCompression> {};

TEST_P(CompressedGltfRefused, WithOneLineNamingTheProblem)
{
  testing::ScratchFolder folder;
  writeAltered(testing::icosphere(3), folder / "bad.glb", GetParam().change);
  try {
    readMesh(folder / "bad.glb");
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(GetParam().mentions), std::string::npos) << e.what();
  }
}

nlohmann::json& meshopt(nlohmann::json& json, int view)
{
  return json["bufferViews"][view]["extensions"]["EXT_meshopt_compression"];
}

INSTANTIATE_TEST_SUITE_P(
    Table, CompressedGltfRefused,
    ::testing::Values(
        BadCompression{
            "corrupt_data",
            [](nlohmann::json&, std::vector<unsigned char>& bin) { std::fill(bin.begin(), bin.begin() + 64, 0xff); },
            "malformed"},
        BadCompression{"count_beyond_budget", [](nlohmann::json& j, auto&) { meshopt(j, 0)["count"] = 1u << 31; },
                       "more bytes than"},
        BadCompression{"past_the_chunk", [](nlohmann::json& j, auto&) { meshopt(j, 1)["byteLength"] = 1u << 30; },
                       "past the binary chunk"},
        BadCompression{"other_buffer", [](nlohmann::json& j, auto&) { meshopt(j, 0)["buffer"] = 1; }, "other than"},
        BadCompression{"unknown_mode", [](nlohmann::json& j, auto&) { meshopt(j, 0)["mode"] = "SPIRAL"; },
                       "unknown mode"},
        BadCompression{"odd_stride", [](nlohmann::json& j, auto&) { meshopt(j, 0)["byteStride"] = 6; }, "byteStride"},
        BadCompression{"negative_count", [](nlohmann::json& j, auto&) { meshopt(j, 0)["count"] = -3; }, "count"},
        BadCompression{"no_mode", [](nlohmann::json& j, auto&) { meshopt(j, 2).erase("mode"); }, "no mode"},
        BadCompression{"filtered_indices", [](nlohmann::json& j, auto&) { meshopt(j, 2)["filter"] = "OCTAHEDRAL"; },
                       "only attributes"},
        BadCompression{"unknown_filter", [](nlohmann::json& j, auto&) { meshopt(j, 1)["filter"] = "FANCY"; }, "FANCY"},
        BadCompression{"not_whole_triangles", [](nlohmann::json& j, auto&) { meshopt(j, 2)["count"] = 7; },
                       "whole triangles"},
        BadCompression{"filter_not_a_name", [](nlohmann::json& j, auto&) { meshopt(j, 1)["filter"] = 3; }, "filter"},
        BadCompression{"buffer_not_an_object", [](nlohmann::json& j, auto&) { j["buffers"][0] = 5; }, "buffer"}),
    [](const ::testing::TestParamInfo<BadCompression>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace lbmshape
