#include "lbmshape/pipeline/frame_writer.hpp"

#include <algorithm>
#include <memory>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "lbmshape/mesh/mesh_reader.hpp"
#include "support/fields.hpp"
#include "support/scratch_folder.hpp"
#include "lbmshape/surface/marching_cubes.hpp"

namespace lbmshape {
namespace {

constexpr int kFrames = 8;
const Extent3 kExtent{24, 24, 24};

GridFrame unitGrid() { return GridFrame{glm::dvec3(0.0), 1.0, kExtent}; }

// Frame k: a sphere of radius 5 + k cells, so every frame's mesh differs.
std::shared_ptr<const Volume> sphereOfFrame(int k)
{
  return std::make_shared<const Volume>(testing::sphereDistance(kExtent, 11.5, 11.5, 11.5, 5.0 + k));
}

// The names in the folder: the frames' and any other (a temporary file left).
std::set<std::string> namesIn(const std::filesystem::path& folder)
{
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

// Every frame is made on one thread and committed on another: all of them
// end under their names, each the mesh of its own field, and no temporary
// file is left beside them.
TEST(FrameWriter, EveryFrameIsCommittedAsItsOwnMeshAndNoTemporaryFileStays)
{
  testing::ScratchFolder folder;
  FrameWriter writer(unitGrid(), folder.path(), ".obj", kFrames, FrameWriter::Keep::LastFrame);
  for (int k = 0; k < kFrames; ++k) writer.push(k, sphereOfFrame(k));
  writer.finish();

  std::set<std::string> expected;
  for (int k = 0; k < kFrames; ++k) expected.insert(writer.framePath(k).filename().string());
  EXPECT_EQ(namesIn(folder.path()), expected);
  for (int k = 0; k < kFrames; ++k) {
    const TriangleMesh written = readMesh(writer.framePath(k));
    EXPECT_EQ(written.triangleCount(), extractSurface(*sphereOfFrame(k), unitGrid()).triangleCount()) << "frame " << k;
  }
}

// Stopped at once, with frames queued, being made and being committed: the
// frames left are whole and the first ones (what stop() counts), and the
// dropped frames' temporary files are gone.
TEST(FrameWriter, StopLeavesTheFirstFramesWholeAndNothingElse)
{
  for (int attempt = 0; attempt < 4; ++attempt) {
    testing::ScratchFolder folder;
    FrameWriter writer(unitGrid(), folder.path(), ".obj", kFrames, FrameWriter::Keep::LastFrame);
    for (int k = 0; k < 3; ++k) writer.push(k, sphereOfFrame(k));
    const int complete = writer.stop();
    ASSERT_GE(complete, 0);
    ASSERT_LE(complete, 3);
    std::set<std::string> expected;
    for (int k = 0; k < complete; ++k) expected.insert(writer.framePath(k).filename().string());
    EXPECT_EQ(namesIn(folder.path()), expected) << "attempt " << attempt;
    for (int k = 0; k < complete; ++k)
      EXPECT_EQ(readMesh(writer.framePath(k)).triangleCount(),
                extractSurface(*sphereOfFrame(k), unitGrid()).triangleCount());
  }
}

// The commits' time is counted on its own (commitMs), not in the write
// stage's, and only where there are files to commit.
TEST(FrameWriter, CountsTheCommitsTimeApartAndOnlyForFiles)
{
  testing::ScratchFolder folder;
  FrameWriter files(unitGrid(), folder.path(), ".obj", kFrames, FrameWriter::Keep::LastFrame);
  for (int k = 0; k < kFrames; ++k) files.push(k, sphereOfFrame(k));
  files.finish();
  EXPECT_GT(files.commitMs(), 0.0);
  EXPECT_GT(files.writeMs(), 0.0);

  int handed = 0;
  FrameWriter sink(
      unitGrid(), [&](int, const TriangleMesh&) { ++handed; }, kFrames, FrameWriter::Keep::LastFrame);
  for (int k = 0; k < kFrames; ++k) sink.push(k, sphereOfFrame(k));
  sink.finish();
  EXPECT_EQ(handed, kFrames);
  EXPECT_EQ(sink.commitMs(), 0.0);
}

}  // namespace
}  // namespace lbmshape
