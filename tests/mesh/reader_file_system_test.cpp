// What a mesh path, or a glTF file's buffer URI, may make lbmshape open: a
// regular file only (a FIFO would block, a folder is no file), and for glTF
// buffers only files inside the glTF file's folder.
#include <fstream>
#include <functional>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "lbmshape/core/error.hpp"
#include "mesh/hand_made_gltf.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;
namespace meshio = testing::meshio;

std::string refusalOf(const std::function<void()>& read)
{
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "read without an error";
}

void makeFifo(const fs::path& path) { ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0) << path; }

// A tetrahedron whose buffer is the file `uri`, written beside it as `bin` (if given).
fs::path gltfWithBuffer(const fs::path& folder, const std::string& uri)
{
  meshio::HandMadeGltf gltf;
  gltf.addMesh(gltf.addPositions(meshio::tetraCorners), gltf.addIndices(meshio::tetraIndices));
  gltf.json["nodes"] = {{{"mesh", 0}}};
  gltf.writeGltf(folder / "model.gltf");  // writes model.bin beside it
  auto json = nlohmann::json::parse(std::ifstream(folder / "model.gltf"));
  json["buffers"][0]["uri"] = uri;
  std::ofstream(folder / "model.gltf") << json.dump();
  return folder / "model.gltf";
}

TEST(MeshPath, AFifoIsRefusedWithoutWaitingForAWriter)
{
  testing::ScratchFolder folder;
  makeFifo(folder / "pipe.obj");
  EXPECT_NE(refusalOf([&] { readMesh(folder / "pipe.obj"); }).find("FIFO"), std::string::npos);
}

TEST(MeshPath, AFolderIsRefused)
{
  testing::ScratchFolder folder;
  fs::create_directory(folder / "folder.ply");
  EXPECT_NE(refusalOf([&] { readMesh(folder / "folder.ply"); }).find("it is a folder"), std::string::npos);
}

TEST(GltfBuffer, InASubfolderIsRead)
{
  testing::ScratchFolder folder;
  const fs::path gltf = gltfWithBuffer(folder.path(), "data/model%20buffer.bin");
  fs::create_directory(folder / "data");
  fs::rename(folder / "model.bin", folder / "data" / "model buffer.bin");
  EXPECT_EQ(readMesh(gltf).triangleCount(), 4u);
}

TEST(GltfBuffer, NamingAFolderIsRefused)
{
  testing::ScratchFolder folder;
  const fs::path gltf = gltfWithBuffer(folder.path(), "sub");
  fs::create_directory(folder / "sub");
  const std::string message = refusalOf([&] { readMesh(gltf); });
  EXPECT_NE(message.find("cannot read " + gltf.string()), std::string::npos) << message;
  EXPECT_NE(message.find("it is a folder"), std::string::npos) << message;
}

TEST(GltfBuffer, NamingAFifoIsRefusedWithoutWaiting)
{
  testing::ScratchFolder folder;
  const fs::path gltf = gltfWithBuffer(folder.path(), "pipe.bin");
  makeFifo(folder / "pipe.bin");
  EXPECT_NE(refusalOf([&] { readMesh(gltf); }).find("FIFO"), std::string::npos);
}

// Shorter than declared is refused, saying how long it is; longer (padding,
// which the glTF validator accepts) is read as its first byteLength bytes.
TEST(GltfBuffer, ShorterThanDeclaredIsRefusedAndLongerIsRead)
{
  testing::ScratchFolder folder;
  const fs::path gltf = gltfWithBuffer(folder.path(), "model.bin");
  const auto size = fs::file_size(folder / "model.bin");
  std::ofstream(folder / "model.bin", std::ios::app) << std::string(4, '\0');
  EXPECT_EQ(readMesh(gltf).triangleCount(), 4u);
  fs::resize_file(folder / "model.bin", size - 1);
  const std::string message = refusalOf([&] { readMesh(gltf); });
  EXPECT_NE(message.find("has " + std::to_string(size - 1) + " bytes, fewer than the " + std::to_string(size) +
                         " its buffer declares"),
            std::string::npos)
      << message;
}

// A file name beyond ASCII is named as it is, not as question marks.
TEST(GltfBuffer, AMissingFileIsNamedInItsOwnLetters)
{
  testing::ScratchFolder folder;
  const fs::path gltf = gltfWithBuffer(folder.path(), "donn%C3%A9es%20%C3%BC.bin");
  const std::string message = refusalOf([&] { readMesh(gltf); });
  EXPECT_NE(message.find("données ü.bin"), std::string::npos) << message;
}

TEST(GltfBuffer, MissingIsAnInputErrorNamingIt)
{
  testing::ScratchFolder folder;
  const fs::path gltf = gltfWithBuffer(folder.path(), "absent.bin");
  const std::string message = refusalOf([&] { readMesh(gltf); });
  EXPECT_NE(message.find("absent.bin"), std::string::npos) << message;
  EXPECT_NE(message.find("no such file"), std::string::npos) << message;
}

TEST(GltfBuffer, OutsideTheFolderIsNeverOpenedEvenWhenItExists)
{
  // A file that does exist one folder up: a URI with ".." is refused by its
  // form, before any file is looked at.
  testing::ScratchFolder folder;
  fs::create_directory(folder / "inner");
  gltfWithBuffer(folder.path(), "model.bin");
  const fs::path gltf = gltfWithBuffer(folder / "inner", "../model.bin");
  EXPECT_NE(refusalOf([&] { readMesh(gltf); }).find("leaves the glTF file's folder"), std::string::npos);
}

TEST(GltfBuffer, ASymbolicLinkOutOfTheFolderIsRefused)
{
  testing::ScratchFolder folder;
  fs::create_directory(folder / "inner");
  gltfWithBuffer(folder.path(), "model.bin");  // the real buffer, one folder up
  const fs::path gltf = gltfWithBuffer(folder / "inner", "link.bin");
  fs::create_symlink(folder / "model.bin", folder / "inner" / "link.bin");
  EXPECT_NE(refusalOf([&] { readMesh(gltf); }).find("leads out of the glTF file's folder"), std::string::npos);
}

TEST(GltfBuffer, ASymbolicLinkInsideTheFolderIsFollowed)
{
  testing::ScratchFolder folder;
  const fs::path gltf = gltfWithBuffer(folder.path(), "link.bin");
  fs::create_symlink(folder / "model.bin", folder / "link.bin");
  EXPECT_EQ(readMesh(gltf).triangleCount(), 4u);
}

TEST(GltfImage, IsNeverOpened)
{
  // lbmshape reads no images: an image URI that names a FIFO would block a
  // reader that opened it.
  testing::ScratchFolder folder;
  const fs::path gltf = gltfWithBuffer(folder.path(), "model.bin");
  auto json = nlohmann::json::parse(std::ifstream(gltf));
  json["images"] = {{{"uri", "texture.png"}}, {{"uri", "../../../../etc/passwd"}}};
  std::ofstream(gltf) << json.dump();
  makeFifo(folder / "texture.png");
  EXPECT_EQ(readMesh(gltf).triangleCount(), 4u);
}

}  // namespace
}  // namespace lbmshape
