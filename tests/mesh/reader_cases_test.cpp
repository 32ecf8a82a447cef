// Every reader on files made byte by byte (support/mesh_file_cases.hpp):
// well-formed files in each format's variants read as the shape they hold;
// malformed and hostile ones are an InputError that names the file and
// says what is wrong, in one line. Read from memory and from a file alike.
#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/text_scan.hpp"
#include "support/mesh_file_cases.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;
using testing::MeshFileCase;

MeshFormat formatOf(const MeshFileCase& c) { return *meshFormatOf("x" + c.extension); }

class WellFormedFile : public ::testing::TestWithParam<MeshFileCase> {};

TEST_P(WellFormedFile, ReadsAsTheClosedShapeItHolds)
{
  const MeshFileCase& c = GetParam();
  const TriangleMesh mesh = readMesh(MeshSource{c.bytes(), c.name, std::nullopt}, formatOf(c));
  // A tetrahedron (1/6) or a unit cube (1), faces outward, whatever the variant.
  const double volume = meshio::signedVolume(mesh);
  EXPECT_TRUE(std::abs(volume - 1.0 / 6.0) < 1e-6 || std::abs(volume - 1.0) < 1e-6) << "volume " << volume;
  EXPECT_TRUE(mesh.triangleCount() == 4 || mesh.triangleCount() == 12) << mesh.triangleCount() << " triangles";
}

TEST_P(WellFormedFile, ReadsTheSameFromAFile)
{
  const MeshFileCase& c = GetParam();
  testing::ScratchFolder folder;
  meshio::writeText(folder / (c.name + c.extension), c.bytes());
  const TriangleMesh fromFile = readMesh(folder / (c.name + c.extension));
  const TriangleMesh fromMemory = readMesh(MeshSource{c.bytes(), c.name, std::nullopt}, formatOf(c));
  EXPECT_EQ(fromFile.positions, fromMemory.positions);
  EXPECT_EQ(fromFile.triangles, fromMemory.triangles);
}

INSTANTIATE_TEST_SUITE_P(Cases, WellFormedFile, ::testing::ValuesIn(testing::wellFormedMeshFiles()),
                         [](const auto& info) { return info.param.name; });

class HostileFile : public ::testing::TestWithParam<MeshFileCase> {};

void expectRefused(const std::function<void()>& read, const std::string& name, const std::string& phrase)
{
  try {
    read();
    FAIL() << "read without an error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cannot read " + name + ": "), std::string::npos) << message;
    EXPECT_NE(message.find(phrase), std::string::npos) << "should say '" << phrase << "': " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    // Printable ASCII, and file names in their own letters (printable UTF-8).
    for (size_t i = 0; i < message.size();) {
      const auto ch = static_cast<unsigned char>(message[i]);
      const size_t length =
          ch >= 0x20 && ch < 0x7f ? 1 : text::printableUtf8Length(std::string_view(message).substr(i));
      ASSERT_GT(length, 0u) << "printable: " << message;
      i += length;
    }
  }
}

TEST_P(HostileFile, IsAnInputErrorThatSaysWhatIsWrong)
{
  const MeshFileCase& c = GetParam();
  expectRefused([&] { readMesh(MeshSource{c.bytes(), c.name, std::nullopt}, formatOf(c)); }, c.name, c.refusal);
}

TEST_P(HostileFile, IsRefusedTheSameWayFromAFile)
{
  const MeshFileCase& c = GetParam();
  testing::ScratchFolder folder;
  const auto path = folder / (c.name + c.extension);
  meshio::writeText(path, c.bytes());
  expectRefused([&] { readMesh(path); }, path.string(), c.refusal);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{path.filename().string()}) << "nothing written";
}

INSTANTIATE_TEST_SUITE_P(Cases, HostileFile, ::testing::ValuesIn(testing::hostileMeshFiles()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace lbmshape
