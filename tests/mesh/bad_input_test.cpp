// Everything that can be wrong with a file going in or coming out is an
// error of the right kind (exit code), with a one-line message that names
// the file, and leaves no file behind.
#include <cstring>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <unistd.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/gltf_animation.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;

namespace fs = std::filesystem;

struct BadCase {
  std::string name;
  ExitCode expected;
  // Prepares the folder and returns the path the error must name.
  std::function<fs::path(const fs::path& folder)> prepare;
  // Reads or writes that path; must throw.
  std::function<void(const fs::path& path)> run;
};

void read(const fs::path& path) { readMesh(path); }
void write(const fs::path& path) { writeMesh(testing::box({0, 0, 0}, {1, 1, 1}), path); }

fs::path objFile(const fs::path& folder, const std::string& text)
{
  meshio::writeText(folder / "input.obj", text);
  return folder / "input.obj";
}

std::vector<unsigned char> garbage(size_t size)
{
  std::mt19937 random(7);
  std::vector<unsigned char> bytes(size);
  for (auto& b : bytes) b = static_cast<unsigned char>(random());
  return bytes;
}

// A binary little-endian PLY file of one tetrahedron whose first vertex is NaN.
fs::path plyWithNaN(const fs::path& folder)
{
  std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  std::vector<unsigned char> bytes(header.begin(), header.end());
  auto put = [&](const auto& value) {
    const auto* p = reinterpret_cast<const unsigned char*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof value);
  };
  for (float v : {std::nanf(""), 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f}) put(v);
  for (auto face : {std::array<int, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
    put(uint8_t(3));
    for (int i : face) put(i);
  }
  meshio::writeBytes(folder / "nan.ply", bytes);
  return folder / "nan.ply";
}

const std::string tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

std::vector<BadCase> badCases()
{
  auto garbageAs = [](std::string name) {
    return [name](const fs::path& folder) {
      meshio::writeBytes(folder / name, garbage(4096));
      return folder / name;
    };
  };
  return {
      {"MissingFile", ExitCode::Input, [](const fs::path& f) { return f / "absent.obj"; }, read},
      {"EmptyFile", ExitCode::Input, [](const fs::path& f) { return objFile(f, ""); }, read},
      {"BinaryGarbageNamedObj", ExitCode::Input, garbageAs("garbage.obj"), read},
      {"BinaryGarbageNamedPly", ExitCode::Input, garbageAs("garbage.ply"), read},
      {"BinaryGarbageNamedOff", ExitCode::Input, garbageAs("garbage.off"), read},
      {"BinaryGarbageNamedStl", ExitCode::Input, garbageAs("garbage.stl"), read},
      {"BinaryGarbageNamedGltf", ExitCode::Input, garbageAs("garbage.gltf"), read},
      {"BinaryGarbageNamedGlb", ExitCode::Input, garbageAs("garbage.glb"), read},
      {"CommentsButNoTriangles", ExitCode::Input, [](const fs::path& f) { return objFile(f, "# nothing\nv 0 0 0\n"); },
       read},
      {"NaNCoordinateInObj", ExitCode::Input,
       [](const fs::path& f) { return objFile(f, "v nan 0 0\n" + tetra.substr(8)); }, read},
      {"InfiniteCoordinateInObj", ExitCode::Input,
       [](const fs::path& f) { return objFile(f, "v 0 0 inf\n" + tetra.substr(8)); }, read},
      {"NaNCoordinateInBinaryPly", ExitCode::Input, plyWithNaN, read},
      {"SingleTriangle", ExitCode::Input,
       [](const fs::path& f) { return objFile(f, "v 0 0 0\nv 1 0 0\nv 0 1 1\nf 1 2 3\n"); }, read},
      {"ZeroExtentBoundingBox", ExitCode::Input,
       [](const fs::path& f) { return objFile(f, "v 0 0 2\nv 1 0 2\nv 1 1 2\nv 0 1 2\nf 1 2 3\nf 1 3 4\nf 1 4 2\n"); },
       read},
      {"FlatButTilted", ExitCode::Input,
       [](const fs::path& f) { return objFile(f, "v 0 0 0\nv 1 0 1\nv 1 1 1\nv 0 1 0\nf 1 2 3\nf 1 3 4\n"); }, read},
      {"AllTrianglesDegenerate", ExitCode::Input,
       [](const fs::path& f) { return objFile(f, "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\nf 1 2 3\nf 2 3 4\n"); }, read},
      {"IndexOutOfRange", ExitCode::Input, [](const fs::path& f) { return objFile(f, tetra + "f 1 2 99\n"); }, read},
      {"UnknownInputExtension", ExitCode::Input,
       [](const fs::path& f) {
         meshio::writeText(f / "mesh.xyz", tetra);
         return f / "mesh.xyz";
       },
       read},
      {"InputIsAFolder", ExitCode::Input,
       [](const fs::path& f) {
         fs::create_directory(f / "folder.obj");
         return f / "folder.obj";
       },
       read},
      {"UnknownOutputExtension", ExitCode::Usage, [](const fs::path& f) { return f / "out.xyz"; }, write},
      {"OutputFolderMissing", ExitCode::Output, [](const fs::path& f) { return f / "missing" / "out.obj"; }, write},
      {"OutputFolderIsAFile", ExitCode::Output,
       [](const fs::path& f) {
         meshio::writeText(f / "file", "");
         return f / "file" / "out.glb";
       },
       write},
      {"UnwritableOutputFolder", ExitCode::Output,
       [](const fs::path& f) {
         // Permissions do not stop root, but nobody may create files in /sys.
         if (::geteuid() == 0) return fs::path("/sys/lbmshape-test.ply");
         fs::create_directory(f / "locked");
         fs::permissions(f / "locked", fs::perms::owner_read | fs::perms::owner_exec);
         return f / "locked" / "out.ply";
       },
       write},
      {"EmptyMeshOutput", ExitCode::Output, [](const fs::path& f) { return f / "empty.obj"; },
       [](const fs::path& p) { writeMesh(TriangleMesh{}, p); }},
      {"NaNMeshOutput", ExitCode::Output, [](const fs::path& f) { return f / "nan.glb"; },
       [](const fs::path& p) {
         TriangleMesh mesh = testing::box({0, 0, 0}, {1, 1, 1});
         mesh.positions[3].y = std::nan("");
         writeMesh(mesh, p);
       }},
      // A .glb, .ply, .stl or .off keeps floats: beyond 3.4e38 a coordinate
      // would be written as infinity (a glTF's bounds null).
      {"CoordinateBeyondSinglePrecisionInAGlb", ExitCode::Output, [](const fs::path& f) { return f / "huge.glb"; },
       [](const fs::path& p) {
         writeMesh(testing::box({0, 0, 0}, {1e39, 1, 1}), p);
       }},
      {"CoordinateBeyondSinglePrecisionInAPly", ExitCode::Output, [](const fs::path& f) { return f / "huge.ply"; },
       [](const fs::path& p) {
         writeMesh(testing::box({-1e300, 0, 0}, {1, 1, 1}), p);
       }},
      {"CoordinateBeyondSinglePrecisionInAnimation", ExitCode::Output,
       [](const fs::path& f) { return f / "morph.glb"; },
       [](const fs::path& p) {
         writeGltfAnimation({testing::box({0, 0, 0}, {1, 1, 1e39})}, 24, p);
       }},
      {"AnimationWithObjExtension", ExitCode::Usage, [](const fs::path& f) { return f / "morph.obj"; },
       [](const fs::path& p) { writeGltfAnimation({testing::icosphere(0)}, 24, p); }},
      {"AnimationWithoutFrames", ExitCode::Usage, [](const fs::path& f) { return f / "morph.glb"; },
       [](const fs::path& p) { writeGltfAnimation({}, 24, p); }},
      {"AnimationAtZeroFramesPerSecond", ExitCode::Usage, [](const fs::path& f) { return f / "morph.glb"; },
       [](const fs::path& p) { writeGltfAnimation({testing::icosphere(0)}, 0.0, p); }},
  };
}

// Names the case in test listings (instead of a dump of its bytes).
void PrintTo(const BadCase& c, std::ostream* out) { *out << c.name; }

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, FailsWithTheRightErrorNamingTheFileAndLeavesNothing)
{
  const BadCase& c = GetParam();
  testing::ScratchFolder folder;
  const fs::path path = c.prepare(folder.path());
  const auto before = folder.entries();
  try {
    c.run(path);
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.code(), c.expected) << message;
    EXPECT_NE(message.find(path.string()), std::string::npos) << "the message names the file: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
  EXPECT_EQ(folder.entries(), before) << "nothing was written";
  if (path.parent_path().parent_path() == folder.path() && fs::is_directory(path.parent_path())) {
    EXPECT_TRUE(fs::is_empty(path.parent_path())) << "nothing was written in " << path.parent_path();
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInput, ::testing::ValuesIn(badCases()),
                         [](const auto& info) { return info.param.name; });

TEST(BadInputMessages, SayWhatIsWrong)
{
  // The message is for the user: spot-check that it names the problem, not only the file.
  testing::ScratchFolder folder;
  auto messageOf = [](auto&& action) -> std::string {
    try {
      action();
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(messageOf([&] { readMesh(folder / "absent.obj"); }).find("no such file"), std::string::npos);
  EXPECT_NE(messageOf([&] { readMesh(objFile(folder.path(), "v nan 0 0\n" + tetra.substr(8))); }).find("line 1"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { readMesh(objFile(folder.path(), tetra + "f 1 2 99\n")); }).find("99"), std::string::npos);
  EXPECT_NE(messageOf([&] {
              readMesh(objFile(folder.path(), "v 0 0 0\nv 1 0 0\nv 0 1 1\nf 1 2 3\n"));
            }).find("single triangle"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { readMesh(plyWithNaN(folder.path())); }).find("vertex 1"), std::string::npos);
  // A damaged vertex line (a NUL before it, a no-break space after "v"),
  // which passed over would put later faces on the wrong vertices.
  for (const std::string& damaged : {std::string("\0v 0 1 0\n", 9), std::string("v\xc2\xa0"
                                                                                "0 1 0\n")}) {
    const std::string text = "v 0 0 0\nv 1 0 0\n" + damaged + "v 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    EXPECT_NE(messageOf([&] { readMesh(objFile(folder.path(), text)); }).find("line 3"), std::string::npos)
        << ::testing::PrintToString(damaged);
  }
  EXPECT_NE(messageOf([&] { writeMesh(testing::icosphere(0), folder / "out.fbx"); }).find(".fbx"), std::string::npos);
}

// One stray vertex far from the rest would shrink the rest into less than a
// voxel of any grid: refused, by number; two parts far apart are a mesh.
TEST(BadInputMessages, AStrayVertexFarFromTheRestIsNamed)
{
  testing::ScratchFolder folder;
  auto textOf = [](const TriangleMesh& mesh) {
    std::string text;
    for (const auto& p : mesh.positions)
      text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (const auto& t : mesh.triangles)
      text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
    return text;
  };
  TriangleMesh stray = testing::icosphere(3);
  const size_t sphereVertices = stray.positions.size();
  // A triangle of its own, far out (one joined to the sphere would be a
  // sliver, dropped as degenerate).
  stray.positions.insert(stray.positions.end(), {{1e30, 0.0, 0.0}, {1e30, 1e29, 0.0}, {1e30, 0.0, 1e29}});
  stray.triangles.push_back({uint32_t(sphereVertices), uint32_t(sphereVertices + 1), uint32_t(sphereVertices + 2)});
  try {
    readMesh(objFile(folder.path(), textOf(stray)));
    ADD_FAILURE() << "a stray vertex at 1e30 was read";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("vertex " + std::to_string(sphereVertices + 2) + " at (1e+30, 1e+29, 0)"), std::string::npos)
        << message;
    EXPECT_NE(message.find("from the rest of the mesh"), std::string::npos) << message;
  }

  TriangleMesh twoParts = testing::icosphere(3), far = testing::icosphere(3);
  for (const auto& p : far.positions) twoParts.positions.push_back(p + glm::dvec3(300.0, 0.0, 0.0));
  for (const auto& t : far.triangles)
    twoParts.triangles.push_back(t + uint32_t(testing::icosphere(3).positions.size()));
  EXPECT_EQ(readMesh(objFile(folder.path(), textOf(twoParts))).triangleCount(), 2 * far.triangleCount());
}

// Copies of a triangle (the same corners in the same turn) are dropped on
// reading, with a warning: a hierarchy cannot separate them, and a million
// of them kept the distances busy for minutes. A triangle and its reverse
// are not copies.
TEST(RepeatedTriangles, CopiesAreDroppedAndTheReverseKept)
{
  testing::ScratchFolder folder;
  const TriangleMesh cube = testing::box({0, 0, 0}, {1, 1, 1});
  std::string text;
  for (const auto& p : cube.positions)
    text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  const auto face = [](uint32_t a, uint32_t b, uint32_t c) {
    return "f " + std::to_string(a + 1) + " " + std::to_string(b + 1) + " " + std::to_string(c + 1) + "\n";
  };
  for (const auto& t : cube.triangles) text += face(t[0], t[1], t[2]);
  const glm::uvec3 first = cube.triangles.front();
  for (int copy = 0; copy < 1000; ++copy) {
    text += face(first[0], first[1], first[2]);
    text += face(first[1], first[2], first[0]);  // the same triangle, from another corner
  }
  text += face(first[0], first[2], first[1]);  // its reverse
  const TriangleMesh read = readMesh(objFile(folder.path(), text));
  EXPECT_EQ(read.triangleCount(), cube.triangleCount() + 1);
  EXPECT_EQ(read.triangles.back(), glm::uvec3(first[0], first[2], first[1]));

  // In a soup (STL, a vertex per corner) by position, as in an indexed mesh.
  TriangleMesh soup;
  for (int copy = 0; copy < 3; ++copy)
    for (const auto& t : cube.triangles) {
      const uint32_t base = uint32_t(soup.positions.size());
      for (int k = 0; k < 3; ++k) soup.positions.push_back(cube.positions[t[k]]);
      soup.triangles.push_back({base, base + 1, base + 2});
    }
  const fs::path stl = folder.path() / "soup.stl";
  writeMesh(soup, stl);
  EXPECT_EQ(readMesh(stl).triangleCount(), cube.triangleCount());
}

TEST(FailedWrite, LeavesThePreviousFileAlone)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(0), folder / "kept.obj");
  TriangleMesh broken = testing::icosphere(1);
  broken.positions[0].x = std::numeric_limits<double>::infinity();
  EXPECT_THROW(writeMesh(broken, folder / "kept.obj"), OutputError);
  EXPECT_EQ(readMesh(folder / "kept.obj").triangleCount(), 20u);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"kept.obj"});
}

}  // namespace
}  // namespace lbmshape
