// Reading keeps the file as a triangle soup: polygons become fans, every
// face survives (manifold or not), and only zero-area triangles are dropped.
#include <gtest/gtest.h>

#include "lbmshape/mesh/mesh_reader.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;

const char* cubeOfQuads = R"(# a unit cube of six quads, in the many ways OBJ allows
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vt 0 0
vn 0 0 1
f 1 4 3 2
f 5/1 6/1 7/1 8/1
f 1//1 2//1 6//1 5//1
f 2/1/1 3/1/1 7/1/1 6/1/1
f -5 -1 -2 -6
f -8 -4 -1 -5
)";

TEST(SoupReading, PolygonsAreFanTriangulated)
{
  testing::ScratchFolder folder;
  meshio::writeText(folder / "cube.obj", cubeOfQuads);
  const TriangleMesh cube = readMesh(folder / "cube.obj");
  EXPECT_EQ(cube.vertexCount(), 8u);
  EXPECT_EQ(cube.triangleCount(), 12u);
  EXPECT_NEAR(meshio::signedVolume(cube), 1.0, 1e-12) << "the fans keep each quad's winding";
  EXPECT_TRUE(cube.normals.empty());
}

TEST(SoupReading, ThreeFacesOnOneEdgeAreAllKept)
{
  // Two tetrahedra glued along edge 1-2 and a third triangle on that edge:
  // non-manifold, which OpenMesh's TriMesh would drop with a warning.
  testing::ScratchFolder folder;
  meshio::writeText(folder / "fins.off",
                    "OFF\n6 7 0\n"
                    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.3 0.3 -1\n-1 -1 0.5\n"
                    "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 1 2 4\n3 2 1 5\n3 5 1 4\n");
  EXPECT_EQ(readMesh(folder / "fins.off").triangleCount(), 7u);
}

TEST(SoupReading, DegenerateTrianglesAreDroppedTheRestKept)
{
  testing::ScratchFolder folder;
  meshio::writeText(folder / "cube.obj", std::string(cubeOfQuads) +
                                             "f 1 1 2\n"  // a repeated corner
                                             "v 2 0 0\n"
                                             "f 1 2 9\n");  // three corners on one line
  const TriangleMesh cube = readMesh(folder / "cube.obj");
  EXPECT_EQ(cube.triangleCount(), 12u);
  EXPECT_EQ(cube.vertexCount(), 9u) << "vertices are kept even when no triangle uses them";
}

TEST(SoupReading, OpenMeshesAreFine)
{
  TriangleMesh open = testing::icosphere(1);
  open.triangles.resize(70);  // ten triangles short of closed
  testing::ScratchFolder folder;
  meshio::writeText(folder / "open.obj", [&] {
    std::string text;
    for (const auto& p : open.positions)
      text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (const auto& t : open.triangles)
      text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
    return text;
  }());
  EXPECT_EQ(readMesh(folder / "open.obj").triangleCount(), 70u);
}

TEST(SoupReading, WindowsLineEndingsAndUpperCaseExtension)
{
  testing::ScratchFolder folder;
  std::string text;
  for (const char* c = cubeOfQuads; *c; ++c) *c == '\n' ? text += "\r\n" : text += *c;
  meshio::writeText(folder / "CUBE.OBJ", text);
  EXPECT_EQ(readMesh(folder / "CUBE.OBJ").triangleCount(), 12u);
}

}  // namespace
}  // namespace lbmshape
