// Vertex colours as scans carry them: glTF COLOR_0 (linear, float or
// normalized bytes, converted to the sRGB the pictures show), PLY
// red/green/blue (bytes or floats) and OBJ "v x y z r g b" lines.
#include <cmath>
#include <fstream>
#include <tuple>

#include <gtest/gtest.h>

#include "mesh/hand_made_gltf.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/scratch_folder.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;

void expectColour(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-4f)
{
  EXPECT_NEAR(actual.r, expected.r, tolerance);
  EXPECT_NEAR(actual.g, expected.g, tolerance);
  EXPECT_NEAR(actual.b, expected.b, tolerance);
}

float srgb(float linear)
{
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

TEST(VertexColours, GltfColour0IsReadAndShownInSrgb)
{
  testing::ScratchFolder folder;
  meshio::HandMadeGltf gltf;
  const int positions = gltf.addPositions(meshio::tetraCorners);
  const int colours = gltf.addColours({{1, 0, 0}, {0, 0.5f, 0}, {0, 0, 0.001f}, {0.2f, 0.2f, 0.2f}});
  const int mesh = gltf.addMesh(positions, gltf.addIndices(meshio::tetraIndices));
  gltf.json["meshes"][mesh]["primitives"][0]["attributes"]["COLOR_0"] = colours;
  gltf.json["nodes"] = {{{"mesh", mesh}}};
  gltf.writeGlb(folder / "m.glb");
  const TriangleMesh read = readMesh(folder / "m.glb");
  ASSERT_EQ(read.colours.size(), 4u);
  expectColour(read.colours[0], {1, 0, 0});
  expectColour(read.colours[1], {0, srgb(0.5f), 0});
  expectColour(read.colours[2], {0, 0, srgb(0.001f)});
  expectColour(read.colours[3], glm::vec3(srgb(0.2f)));
}

TEST(VertexColours, NormalizedBytesAndPrimitivesWithoutColoursAreWhite)
{
  testing::ScratchFolder folder;
  meshio::HandMadeGltf gltf;
  const int plain = gltf.addPositions(meshio::tetraCorners);
  const int indices = gltf.addIndices(meshio::tetraIndices);
  const int coloured = gltf.addColours8({{255, 0, 0, 255}, {0, 255, 0, 0}, {0, 0, 255, 128}, {255, 255, 255, 255}});
  const int mesh = gltf.addMesh(plain, indices);
  nlohmann::json second = gltf.json["meshes"][mesh]["primitives"][0];
  second["attributes"]["COLOR_0"] = coloured;
  gltf.json["meshes"][mesh]["primitives"].push_back(second);  // the same tetrahedron again, coloured
  gltf.json["nodes"] = {{{"mesh", mesh}}};
  gltf.writeGlb(folder / "m.glb");
  const TriangleMesh read = readMesh(folder / "m.glb");
  ASSERT_EQ(read.vertexCount(), 8u);
  ASSERT_EQ(read.colours.size(), 8u);
  for (int v = 0; v < 4; ++v) expectColour(read.colours[size_t(v)], glm::vec3(1.0f));
  expectColour(read.colours[4], {1, 0, 0});
  expectColour(read.colours[6], {0, 0, 1});
}

TEST(VertexColours, AGltfWithoutColoursHasNone)
{
  testing::ScratchFolder folder;
  meshio::HandMadeGltf gltf;
  const int mesh = gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  gltf.json["nodes"] = {{{"mesh", mesh}}};
  gltf.writeGlb(folder / "m.glb");
  EXPECT_TRUE(readMesh(folder / "m.glb").colours.empty());
}

TEST(VertexColours, ColourCountMustMatchThePositions)
{
  testing::ScratchFolder folder;
  meshio::HandMadeGltf gltf;
  const int positions = gltf.addPositions(meshio::tetraCorners);
  const int colours = gltf.addColours({{1, 0, 0}, {0, 1, 0}});
  const int mesh = gltf.addMesh(positions, gltf.addIndices(meshio::tetraIndices));
  gltf.json["meshes"][mesh]["primitives"][0]["attributes"]["COLOR_0"] = colours;
  gltf.json["nodes"] = {{{"mesh", mesh}}};
  gltf.writeGlb(folder / "m.glb");
  try {
    readMesh(folder / "m.glb");
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("COLOR_0"), std::string::npos) << e.what();
  }
}

// An ASCII PLY tetrahedron whose vertices carry `colourProperties` after
// x y z, each vertex line "x y z" followed by its values in `colourValues`.
std::string plyTetrahedron(const std::string& colourProperties, const std::vector<std::string>& colourValues)
{
  std::string ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n" +
                    colourProperties + "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const char* corners[4] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1"};
  for (int v = 0; v < 4; ++v) ply += std::string(corners[v]) + " " + colourValues[size_t(v)] + "\n";
  return ply + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
}

TEST(VertexColours, PlyRedGreenBlueInBytesOrFloats)
{
  testing::ScratchFolder folder;
  std::ofstream(folder / "bytes.ply") << plyTetrahedron(
      "property uchar red\nproperty uchar green\nproperty uchar blue\n",
      {"255 0 0", "0 51 0", "0 0 255", "255 255 255"});
  const TriangleMesh bytes = readMesh(folder / "bytes.ply");
  ASSERT_EQ(bytes.colours.size(), 4u);
  expectColour(bytes.colours[0], {1, 0, 0});
  expectColour(bytes.colours[1], {0, 0.2f, 0});
  std::ofstream(folder / "floats.ply") << plyTetrahedron(
      "property float red\nproperty float green\nproperty float blue\n", {"0.5 0 0", "0 1 0", "0 0 7", "1 1 1"});
  const TriangleMesh floats = readMesh(folder / "floats.ply");
  ASSERT_EQ(floats.colours.size(), 4u);
  expectColour(floats.colours[0], {0.5f, 0, 0});
  expectColour(floats.colours[2], {0, 0, 1});  // clamped to [0, 1]
  std::ofstream(folder / "plain.ply") << plyTetrahedron("property uchar red\n", {"1", "1", "1", "1"});
  EXPECT_TRUE(readMesh(folder / "plain.ply").colours.empty()) << "red alone is not a colour";
}

TEST(VertexColours, ObjVertexLinesWithSixNumbers)
{
  testing::ScratchFolder folder;
  const std::string faces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  std::ofstream(folder / "coloured.obj") << "v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0\nv 0 0 1 0 0 2\n" << faces;
  const TriangleMesh coloured = readMesh(folder / "coloured.obj");
  ASSERT_EQ(coloured.colours.size(), 4u);
  expectColour(coloured.colours[0], {1, 0, 0});
  expectColour(coloured.colours[1], {0, 0.5f, 0});
  expectColour(coloured.colours[2], {1, 1, 1});  // a vertex without one is white
  expectColour(coloured.colours[3], {0, 0, 1});  // clamped to [0, 1]
  std::ofstream(folder / "homogeneous.obj") << "v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nv 0 0 1 1\n" << faces;
  EXPECT_TRUE(readMesh(folder / "homogeneous.obj").colours.empty()) << "x y z w has no colour";
}

}  // namespace
}  // namespace lbmshape

namespace lbmshape {
namespace {

// The colours lbmshape writes come back as they went in: glTF COLOR_0
// (float, and normalized bytes when compressed), OBJ, and PLY's red,
// green and blue bytes (they were dropped).
TEST(VertexColours, WrittenColoursReadBack)
{
  testing::ScratchFolder folder;
  TriangleMesh mesh;
  for (const glm::vec3& p : meshio::tetraCorners) mesh.positions.push_back(glm::dvec3(p));
  for (size_t i = 0; i < meshio::tetraIndices.size(); i += 3)
    mesh.triangles.push_back({meshio::tetraIndices[i], meshio::tetraIndices[i + 1], meshio::tetraIndices[i + 2]});
  mesh.colours = {{1, 0, 0}, {0, 0.5f, 0}, {0.2f, 0.4f, 0.8f}, {1, 1, 1}};
  for (const auto& [name, compression, tolerance] :
       {std::tuple{"m.glb", GltfCompression::None, 1e-5f}, std::tuple{"m.gltf", GltfCompression::None, 1e-5f},
        std::tuple{"m.obj", GltfCompression::None, 1e-6f}, std::tuple{"c.glb", GltfCompression::Meshopt, 0.03f},
        std::tuple{"m.ply", GltfCompression::None, 0.51f / 255.f}}) {  // half a byte
    writeMesh(mesh, folder / name, EmptyMesh::Refused, compression);
    const TriangleMesh read = readMesh(folder / name);
    ASSERT_EQ(read.colours.size(), 4u) << name;
    for (size_t v = 0; v < 4; ++v) {
      // Compressed vertices are reordered: find each by its position.
      size_t original = 0;
      while (glm::length(mesh.positions[original] - read.positions[v]) > 1e-3) ++original;
      expectColour(read.colours[v], mesh.colours[original], tolerance);
    }
  }
  const meshio::GlbContent glb = meshio::readGlb(folder / "m.glb");
  EXPECT_TRUE(glb.json["meshes"][0]["primitives"][0]["attributes"].contains("COLOR_0"));
}

}  // namespace
}  // namespace lbmshape
