// Every format lbmshape writes reads back as the same mesh: the same vertex
// and triangle counts and the same corner positions, exactly for OBJ (which
// keeps doubles) and to single precision for the others.
#include <cstring>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/gltf_animation.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "support/glb_json.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;

struct RoundTripCase {
  std::string extension;
  double tolerance;  // relative to the mesh's size
};

// Names the case in test listings (instead of a dump of its bytes).
void PrintTo(const RoundTripCase& c, std::ostream* out) { *out << c.extension; }

class RoundTripEveryFormat : public ::testing::TestWithParam<RoundTripCase> {};

void expectSameCorners(const TriangleMesh& expected, const TriangleMesh& actual, double tolerance)
{
  ASSERT_EQ(actual.triangleCount(), expected.triangleCount());
  for (size_t t = 0; t < expected.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 a = expected.positions[expected.triangles[t][k]], b = actual.positions[actual.triangles[t][k]];
      ASSERT_LE(glm::distance(a, b), tolerance) << "triangle " << t << " corner " << k;
    }
}

TEST_P(RoundTripEveryFormat, KeepsCountsAndPositions)
{
  // Off the origin and not a round size, so that the coordinates use every digit.
  const TriangleMesh sphere = testing::icosphere(2, 1.7, {3.25, -0.5, 12.0});
  testing::ScratchFolder folder;
  const auto path = folder / ("sphere" + GetParam().extension);
  writeMesh(sphere, path);
  const TriangleMesh read = readMesh(path);

  EXPECT_EQ(read.vertexCount(), sphere.vertexCount());
  EXPECT_EQ(read.triangleCount(), sphere.triangleCount());
  const double tolerance = GetParam().tolerance * 14.0;  // |coordinates| <= 14
  expectSameCorners(sphere, read, tolerance);
  // STL has no shared vertices: the reader merges equal positions in the
  // order it meets them, so only the corners can be compared there.
  if (GetParam().extension != ".stl") {
    for (size_t i = 0; i < sphere.positions.size(); ++i)
      ASSERT_LE(glm::distance(sphere.positions[i], read.positions[i]), tolerance);
  }
  EXPECT_EQ(folder.entries(), std::vector<std::string>{path.filename().string()}) << "no temporary file is left behind";
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTripEveryFormat,
                         ::testing::Values(RoundTripCase{".obj", 0.0}, RoundTripCase{".ply", 2e-7},
                                           RoundTripCase{".off", 2e-7}, RoundTripCase{".stl", 2e-7},
                                           RoundTripCase{".gltf", 2e-7}, RoundTripCase{".glb", 2e-7},
                                           RoundTripCase{".OBJ", 0.0}, RoundTripCase{".Glb", 2e-7}),
                         [](const auto& info) {
                           std::string name = info.param.extension.substr(1);
                           return name == "OBJ" || name == "Glb" ? name + "_upper_case" : name;
                         });

TEST(RoundTrip, ObjKeepsEveryBitOfADoubleFarFromTheOrigin)
{
  // 1e6 units away with detail at 1e-7: float would keep none of it.
  const TriangleMesh far = testing::icosphere(1, 3e-7, {1e6 + 0.123456789, -2e6, 7.0});
  testing::ScratchFolder folder;
  writeMesh(far, folder / "far.obj");
  const TriangleMesh read = readMesh(folder / "far.obj");
  ASSERT_EQ(read.positions.size(), far.positions.size());
  for (size_t i = 0; i < far.positions.size(); ++i) EXPECT_EQ(read.positions[i], far.positions[i]) << "vertex " << i;
}

// Writing `mesh` to `path` is an OutputError whose message holds `phrase`,
// and leaves no file.
void expectRefusedSaying(const TriangleMesh& mesh, const std::filesystem::path& path, const std::string& phrase)
{
  try {
    writeMesh(mesh, path);
    ADD_FAILURE() << path << " was written";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path)) << path;
}

// A georeferenced scan: a mesh 1e6 of its sizes from the origin, where a
// float is 0.0625 wide. glTF keeps it (positions about its centre, the
// centre in its node's translation, in double), compressed or not and in
// an animation; the float-only formats refuse it rather than write
// collapsed triangles; a mesh near the origin is stored as it is.
TEST(RoundTrip, GltfKeepsAMeshFarFromTheOriginAndTheOthersRefuseIt)
{
  const glm::dvec3 centre{1e6 + 0.123456789, -2e6, 5e5};
  const TriangleMesh far = testing::icosphere(3, 1.0, centre);
  testing::ScratchFolder folder;
  // Every vertex on the unit sphere about the centre (compression reorders
  // them, so they are not compared one to one).
  const auto expectKept = [&](const TriangleMesh& read, double tolerance, const std::string& what) {
    ASSERT_EQ(read.triangleCount(), far.triangleCount()) << what;
    for (const glm::dvec3& p : read.positions) ASSERT_NEAR(glm::distance(p, centre), 1.0, tolerance) << what;
  };
  for (const char* extension : {".glb", ".gltf"}) {
    writeMesh(far, folder / (std::string("far") + extension));
    expectKept(readMesh(folder / (std::string("far") + extension)), 2e-7, extension);
  }
  writeMesh(far, folder / "compressed.glb", EmptyMesh::Refused, GltfCompression::Meshopt);
  expectKept(readMesh(folder / "compressed.glb"), 1e-4, "compressed");  // 16-bit quantization of its box
  writeGltfAnimation({far}, 24, folder / "morph.glb");
  expectKept(readMesh(folder / "morph.glb"), 2e-7, "animation");
  writeGltfAnimation({far, far}, 24, folder / "morph.glb");
  // Each frame's node holds the translation itself, so a hidden frame (its
  // node scaled to 0) shrinks to its centre, not to the origin, where a
  // viewer's "frame all" took it as part of the scene.
  const nlohmann::json animation = testing::glbJson(folder / "morph.glb");
  ASSERT_EQ(animation["scenes"][0]["nodes"].size(), 2u);
  for (const auto& root : animation["scenes"][0]["nodes"]) {
    const nlohmann::json& node = animation["nodes"][root.get<int>()];
    ASSERT_TRUE(node.contains("translation")) << node;
    EXPECT_NEAR(
        glm::distance(glm::dvec3(node["translation"][0], node["translation"][1], node["translation"][2]), centre), 0.0,
        0.5)
        << node;
  }
  for (const char* extension : {".ply", ".stl", ".off"})
    expectRefusedSaying(far, folder / (std::string("far") + extension), "write .obj or .glb");
  // Near the origin for its size: the positions as they are, no translation.
  writeMesh(testing::icosphere(2, 1.7, {3.25, -0.5, 12.0}), folder / "near.glb");
  const nlohmann::json near = testing::glbJson(folder / "near.glb");  // held: the loop's range is a part of it
  for (const auto& node : near["nodes"]) EXPECT_FALSE(node.contains("translation"));
}

// A mesh whose edges are below single precision's smallest normal numbers
// collapses whatever the origin: .glb is refused like the others, and the
// message suggests only .obj (it used to suggest .glb to a .glb output).
TEST(RoundTrip, AMeshTooSmallForSinglePrecisionIsOnlyOfferedObj)
{
  const TriangleMesh tiny = testing::icosphere(2, 1e-44, {0.0, 0.0, 0.0});
  testing::ScratchFolder folder;
  for (const char* extension : {".glb", ".ply"})
    expectRefusedSaying(tiny, folder / (std::string("tiny") + extension), "write .obj, which keeps doubles");
  writeMesh(tiny, folder / "tiny.obj");
  EXPECT_EQ(readMesh(folder / "tiny.obj").triangleCount(), tiny.triangleCount());
}

// OBJ keeps doubles, but lbmshape reads no coordinate beyond single
// precision's range: a mesh there (noise of --sigma 1e200) is refused
// rather than written as a file lbmshape could not read back.
TEST(RoundTrip, NoFormatIsWrittenWithCoordinatesBeyondSinglePrecision)
{
  const TriangleMesh huge = testing::icosphere(2, 1e39, {0.0, 0.0, 0.0});
  testing::ScratchFolder folder;
  EXPECT_THROW(writeMesh(huge, folder / "huge.obj"), OutputError);
  EXPECT_FALSE(std::filesystem::exists(folder / "huge.obj"));
  const TriangleMesh large = testing::icosphere(2, 1e37, {0.0, 0.0, 0.0});
  writeMesh(large, folder / "large.obj");
  EXPECT_EQ(readMesh(folder / "large.obj").triangleCount(), large.triangleCount());
}

TEST(RoundTrip, NonManifoldFacesSurviveEveryOpenMeshFormat)
{
  // A box with a fin: a triangle on one of its edges, so that edge has three
  // faces, which OpenMesh's own mesh types would refuse.
  TriangleMesh finned = testing::box({0, 0, 0}, {1, 1, 1});
  finned.positions.push_back({0.5, -1.0, -1.0});
  finned.triangles.push_back({0, 1, 8});
  testing::ScratchFolder folder;
  for (const char* extension : {".obj", ".ply", ".off", ".stl", ".glb"}) {
    const auto path = folder / (std::string("finned") + extension);
    writeMesh(finned, path);
    EXPECT_EQ(readMesh(path).triangleCount(), 13u) << extension;
  }
}

TEST(RoundTrip, PlyCarriesVertexNormalsForSmoothShading)
{
  // Without normals viewers shade a PLY flat, triangle by triangle. On a
  // sphere about the origin each vertex normal points along the vertex.
  const TriangleMesh sphere = testing::icosphere(3);
  testing::ScratchFolder folder;
  writeMesh(sphere, folder / "sphere.ply");
  std::ifstream in(folder / "sphere.ply", std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const size_t body = bytes.find("end_header\n") + 11;
  const std::string header = bytes.substr(0, body);
  ASSERT_NE(header.find("format binary_little_endian"), std::string::npos) << header;
  // x y z nx ny nz, all float, in that order.
  std::vector<std::string> properties;
  for (size_t at = header.find("element vertex"); (at = header.find("property float ", at)) != std::string::npos;) {
    at += 15;
    properties.push_back(header.substr(at, header.find('\n', at) - at));
    if (properties.size() == 6) break;
  }
  ASSERT_EQ(properties, (std::vector<std::string>{"x", "y", "z", "nx", "ny", "nz"})) << header;
  for (size_t v = 0; v < sphere.vertexCount(); ++v) {
    float values[6];
    std::memcpy(values, bytes.data() + body + v * sizeof values, sizeof values);
    const glm::dvec3 normal(values[3], values[4], values[5]);
    EXPECT_NEAR(glm::length(normal), 1.0, 1e-5) << "vertex " << v;
    EXPECT_GT(glm::dot(normal, glm::normalize(sphere.positions[v])), 0.99) << "vertex " << v;
  }
  EXPECT_EQ(readMesh(folder / "sphere.ply").triangleCount(), sphere.triangleCount()) << "and it still reads back";
}

TEST(RoundTrip, WritingReplacesAnExistingFile)
{
  testing::ScratchFolder folder;
  const auto path = folder / "mesh.ply";
  writeMesh(testing::icosphere(0), path);
  writeMesh(testing::icosphere(1), path);
  EXPECT_EQ(readMesh(path).triangleCount(), 80u);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"mesh.ply"});
}

}  // namespace
}  // namespace lbmshape
