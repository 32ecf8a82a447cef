// How lbmshape writes glTF: the GLB container written as it goes is the one
// made in memory, a model written to a file is given back whole, and an
// animation made frame by frame checks its frames as the whole-file call
// does.
#include <fstream>
#include <iterator>
#include <sstream>

#include <gtest/gtest.h>

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/glb_container.hpp"
#include "lbmshape/mesh/glb_stream.hpp"
#include "lbmshape/mesh/gltf_animation.hpp"
#include "lbmshape/mesh/gltf_builder.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

std::string fileBytes(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(GlbContainer, WrittenAsItGoesIsTheFileMadeInMemory)
{
  for (const size_t binaryBytes : {0, 1, 3, 4, 6, 1000}) {
    for (const std::string json : {"{}", "{\"asset\":{\"version\":\"2.0\"}}"}) {
      std::string binary(binaryBytes, '\0');
      for (size_t i = 0; i < binaryBytes; ++i) binary[i] = char(i * 7 + 1);
      std::ostringstream streamed;
      writeGlb(streamed, json, binary);
      const std::string made = glbFile(json, binary);
      EXPECT_EQ(streamed.str(), made) << binaryBytes << " binary bytes";
      EXPECT_EQ(made.size() % 4, 0u);
      EXPECT_EQ(glbWord(made, 8), made.size()) << "the header's length";
      EXPECT_EQ(glbChunks(made).binary.substr(0, binaryBytes), binary);
    }
  }
}

std::vector<unsigned char> someBytes(size_t count, int seed)
{
  std::vector<unsigned char> bytes(count);
  for (size_t i = 0; i < count; ++i) bytes[i] = static_cast<unsigned char>(i * 13 + size_t(seed));
  return bytes;
}

TEST(GlbStream, LeavesRoomForTheJsonAndFillsItLast)
{
  testing::ScratchFolder folder;
  const std::string json = "{\"asset\":{\"version\":\"2.0\"}}";
  GlbStream stream(folder / "s.glb", 100);
  const auto first = someBytes(7, 1), second = someBytes(30, 2);
  stream.append(first);
  stream.append(second);
  EXPECT_EQ(stream.binaryBytes(), 37u);
  EXPECT_FALSE(std::filesystem::exists(folder / "s.glb")) << "nothing under the name before finish()";
  stream.finish(json);
  const std::string glb = fileBytes(folder / "s.glb");
  EXPECT_EQ(glbWord(glb, 8), glb.size());
  EXPECT_EQ(glb.size() % 4, 0u);
  const GlbChunks chunks = glbChunks(glb);
  EXPECT_EQ(chunks.json.size(), 100u) << "the room, padded with spaces";
  EXPECT_EQ(chunks.json.substr(0, json.size()), json);
  EXPECT_EQ(chunks.json.find_first_not_of(' ', json.size()), std::string_view::npos);
  std::string binary(first.begin(), first.end());
  binary.append(second.begin(), second.end());
  EXPECT_EQ(chunks.binary.size(), 40u) << "37 bytes padded to 4";
  EXPECT_EQ(chunks.binary.substr(0, 37), binary);
  EXPECT_EQ(chunks.binary.substr(37), std::string(3, '\0'));
}

TEST(GlbStream, AJsonLongerThanItsRoomWritesTheFileAgain)
{
  testing::ScratchFolder folder;
  const std::string json = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"a generator with a long name\"}}";
  GlbStream stream(folder / "s.glb", 8);
  const auto bytes = someBytes(1001, 3);
  stream.append(bytes);
  stream.finish(json);
  EXPECT_EQ(fileBytes(folder / "s.glb"), glbFile(json, std::string(bytes.begin(), bytes.end())));
  for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
    EXPECT_NE(entry.path().filename().string()[0], '.') << "a temporary file was left: " << entry.path();
}

TEST(GlbStream, WithoutBytesHasNoBinaryChunk)
{
  testing::ScratchFolder folder;
  GlbStream stream(folder / "s.glb", 64);
  stream.finish("{}");
  const std::string glb = fileBytes(folder / "s.glb");
  EXPECT_EQ(glb.size(), 12u + 8u + 64u);
  EXPECT_EQ(glbWord(glb, 8), glb.size());
  EXPECT_TRUE(glbChunks(glb).binary.empty());
}

TEST(SaveGltf, GivesTheModelBackWhole)
{
  GltfBuilder builder;
  builder.addNode(builder.addMesh(testing::icosphere(2), "sphere"), "sphere");
  const std::vector<unsigned char> before = builder.model().buffers.at(0).data;
  ASSERT_FALSE(before.empty());
  testing::ScratchFolder folder;
  for (const char* name : {"first.glb", "second.glb"}) {
    AtomicFile file(folder / name);
    saveGltf(builder.model(), MeshFormat::Glb, file);
    file.commit();
  }
  EXPECT_EQ(builder.model().buffers.at(0).data, before) << "the buffer lent to the writer came back";
  EXPECT_EQ(fileBytes(folder / "first.glb"), fileBytes(folder / "second.glb"));
  const std::string glb = fileBytes(folder / "first.glb");
  const GlbChunks chunks = glbChunks(glb);
  EXPECT_EQ(chunks.binary.substr(0, before.size()),
            std::string_view(reinterpret_cast<const char*>(before.data()), before.size()));
  EXPECT_NE(chunks.json.find("\"byteLength\":" + std::to_string(before.size())), std::string_view::npos) << chunks.json;
}

// A name with a byte that is not UTF-8 (a Latin-1 file name, "caf\xe9"):
// written with U+FFFD in its place; the writer threw, after all the work.
TEST(SaveGltf, ANameThatIsNotUtf8IsWrittenWithAReplacementCharacter)
{
  GltfBuilder builder;
  builder.addNode(builder.addMesh(testing::icosphere(1), "caf\xe9"), "caf\xe9");
  testing::ScratchFolder folder;
  AtomicFile file(folder / "cafe.glb");
  ASSERT_NO_THROW(saveGltf(builder.model(), MeshFormat::Glb, file));
  file.commit();
  const std::string glb = fileBytes(folder / "cafe.glb");
  EXPECT_NE(glbChunks(glb).json.find("\"caf\xef\xbf\xbd\""), std::string_view::npos) << glbChunks(glb).json;
}

TEST(GltfAnimationFrameByFrame, IsTheFileOfAllFramesAtOnce)
{
  testing::ScratchFolder folder;
  const std::vector<TriangleMesh> frames = {testing::icosphere(1), TriangleMesh{}, testing::icosphere(2, 1.5)};
  writeGltfAnimation(frames, 12.0, folder / "at_once.glb");
  GltfAnimation animation(folder / "by_frame.glb", frames.size(), 12.0);
  for (const TriangleMesh& frame : frames) animation.add(frame);
  EXPECT_FALSE(std::filesystem::exists(folder / "by_frame.glb")) << "nothing is written before write()";
  animation.write();
  // The file's name is not in it: the two compare byte for byte.
  EXPECT_EQ(fileBytes(folder / "by_frame.glb"), fileBytes(folder / "at_once.glb"));
}

TEST(GltfAnimationFrameByFrame, RefusesTooFewOrTooManyFramesAndBadOnes)
{
  testing::ScratchFolder folder;
  GltfAnimation animation(folder / "morph.glb", 2, 24.0);
  animation.add(testing::icosphere(1));
  EXPECT_THROW(animation.write(), std::logic_error) << "one frame of two";
  EXPECT_FALSE(std::filesystem::exists(folder / "morph.glb"));
  TriangleMesh broken = testing::icosphere(1);
  broken.triangles.front().x = uint32_t(broken.positions.size());  // past the vertices
  try {
    animation.add(broken);
    FAIL() << "a frame with a triangle past its vertices was taken";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("frame 1"), std::string::npos) << e.what();
  }
  animation.add(testing::icosphere(1));
  EXPECT_THROW(animation.add(testing::icosphere(1)), std::logic_error) << "a third frame of two";
  animation.write();
  EXPECT_TRUE(std::filesystem::exists(folder / "morph.glb"));
  EXPECT_THROW(GltfAnimation(folder / "m.obj", 2, 24.0), UsageError);
  EXPECT_THROW(GltfAnimation(folder / "m.glb", 0, 24.0), UsageError);
  EXPECT_THROW(GltfAnimation(folder / "m.glb", 2, 0.0), UsageError);
}

}  // namespace
}  // namespace lbmshape
