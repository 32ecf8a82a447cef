// AtomicFile: the target appears, or changes, only on commit().
#include <atomic>
#include <chrono>
#include <csignal>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <thread>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/temporary_files.hpp"
#include "lbmshape/mesh/gltf_writer.hpp"
#include "lbmshape/mesh/obj_writer.hpp"
#include "lbmshape/mesh/openmesh_writer.hpp"
#include "mesh/mesh_fixtures.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace meshio = testing::meshio;

std::string contents(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(AtomicFile, TemporaryFileIsBesideTheTargetWithItsExtension)
{
  testing::ScratchFolder folder;
  AtomicFile file(folder / "result.glb");
  EXPECT_EQ(file.temporaryPath().parent_path(), folder.path());
  EXPECT_EQ(file.temporaryPath().extension(), ".glb");
  EXPECT_NE(file.temporaryPath(), file.target());
  EXPECT_TRUE(std::filesystem::exists(file.temporaryPath()));
}

TEST(AtomicFile, CommitMovesTheContentIntoPlace)
{
  testing::ScratchFolder folder;
  {
    AtomicFile file(folder / "out.txt");
    meshio::writeText(file.temporaryPath(), "new");
    file.commit();
  }
  EXPECT_EQ(contents(folder / "out.txt"), "new");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

// A target that is a symbolic link (a render farm's, an asset store's) is
// written through: the file it points to changes and the link stays a
// link; one that points nowhere yet makes the file it points to.
TEST(AtomicFile, ALinkIsWrittenThroughAndStaysALink)
{
  testing::ScratchFolder folder;
  std::filesystem::create_directory(folder / "store");
  meshio::writeText(folder / "store" / "real.glb", "old");
  std::filesystem::create_symlink("store/real.glb", folder / "link.glb");  // relative, read from its folder
  std::filesystem::create_symlink("store/later.glb", folder / "dangling.glb");
  for (const auto& [link, file] : {std::pair{"link.glb", "real.glb"}, std::pair{"dangling.glb", "later.glb"}}) {
    AtomicFile written(folder / link);
    EXPECT_EQ(written.target(), folder / link) << "messages name the path as given";
    EXPECT_EQ(written.temporaryPath().parent_path(), folder / "store") << "beside the file, for an atomic rename";
    meshio::writeText(written.temporaryPath(), std::string("new ") + file);
    written.commit();
    EXPECT_TRUE(std::filesystem::is_symlink(folder / link)) << link;
    EXPECT_EQ(contents(folder / "store" / file), std::string("new ") + file) << link;
    EXPECT_EQ(contents(folder / link), std::string("new ") + file) << link;
  }
}

TEST(AtomicFile, WithoutCommitNothingChanges)
{
  testing::ScratchFolder folder;
  meshio::writeText(folder / "out.txt", "old");
  {
    AtomicFile file(folder / "out.txt");
    meshio::writeText(file.temporaryPath(), "half writ");
    EXPECT_EQ(contents(folder / "out.txt"), "old");
  }  // as when an exception leaves the writer
  EXPECT_EQ(contents(folder / "out.txt"), "old");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, TwoAtOnceDoNotShareATemporaryFile)
{
  testing::ScratchFolder folder;
  AtomicFile a(folder / "frame.obj"), b(folder / "frame.obj");
  EXPECT_NE(a.temporaryPath(), b.temporaryPath());
}

TEST(AtomicFile, MissingFolderIsAnOutputErrorNamingThePath)
{
  testing::ScratchFolder folder;
  const auto target = folder / "no" / "such" / "out.obj";
  try {
    AtomicFile file(target);
    FAIL() << "expected an OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
}

TEST(AtomicFile, TargetThatIsAFolderIsAnOutputError)
{
  testing::ScratchFolder folder;
  std::filesystem::create_directory(folder / "taken.obj");
  EXPECT_THROW(AtomicFile(folder / "taken.obj"), OutputError);
}

// The new file is renamed over the old, which would replace a device or a
// pipe by a plain file (as root, /dev/full was): refused, named, left as
// it was, directly or through a link.
TEST(AtomicFile, ADeviceOrAPipeIsRefusedAndLeftAsItWas)
{
  testing::ScratchFolder folder;
  ASSERT_EQ(::mkfifo((folder / "pipe.glb").c_str(), 0666), 0);
  try {
    AtomicFile file(folder / "pipe.glb");
    FAIL() << "expected an OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a named pipe, not a regular file"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_fifo(folder / "pipe.glb"));
  std::filesystem::create_symlink("/dev/null", folder / "null.glb");
  try {
    AtomicFile file(folder / "null.glb");
    FAIL() << "expected an OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/null is a device, not a regular file"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder.path()), {}), 2);  // no temporary file left
}

// The tag this process's temporary files carry (machine, boot, process-id
// namespace), read off one.
std::string writerTagOfThisProcess(const std::filesystem::path& folder)
{
  AtomicFile probe(folder / "probe.glb");
  const std::string name = probe.temporaryPath().filename().string();  // ".probe.tmp-<tag>-<pid>-<n>.glb"
  const size_t start = name.find(".tmp-") + 5;
  return name.substr(start, name.find('-', start) - start);
}

pid_t aProcessThatIsGone()
{
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  EXPECT_GT(child, 0);
  EXPECT_EQ(::waitpid(child, nullptr, 0), child);  // gone: its id names no process
  return child;
}

// A process killed without unwinding (SIGKILL) leaves its temporary files:
// those of processes that are gone are removed, a live one's, another
// machine's or container's (another tag, in a folder they share) and other
// files are left.
TEST(AtomicFile, ADeadWritersTemporaryFilesAreRemoved)
{
  testing::ScratchFolder folder;
  const std::string tag = writerTagOfThisProcess(folder.path());
  ASSERT_EQ(tag.size(), 16u);
  const std::string gone = std::to_string(aProcessThatIsGone());
  const auto dead = folder / (".frame_0003.tmp-" + tag + "-" + gone + "-7.glb");
  const auto deadUntagged = folder / (".frame_0005.tmp-" + gone + "-7.glb");  // as named before the tag
  const auto live = folder / (".frame_0004.tmp-" + tag + "-" + std::to_string(::getpid()) + "-8.glb");
  const auto elsewhere = folder / (".frame_0006.tmp-0123456789abcdef-" + gone + "-9.glb");
  const auto absurd = folder / (".frame_0007.tmp-" + tag + "-99999999999999999999999999-1.glb");
  const auto other = folder / ".notes.tmp-x.glb";
  const auto frame = folder / "frame_0002.glb";
  for (const auto& path : {dead, deadUntagged, live, elsewhere, absurd, other, frame}) std::ofstream(path) << "x";
  EXPECT_EQ(removeDeadWritersTemporaryFiles(folder.path()), 2u);
  EXPECT_FALSE(std::filesystem::exists(dead));
  EXPECT_FALSE(std::filesystem::exists(deadUntagged));
  for (const auto& path : {live, elsewhere, absurd, other, frame}) EXPECT_TRUE(std::filesystem::exists(path)) << path;
}

// A denoise killed while it wrote (the out-of-memory killer) left its
// temporary file beside the output for ever: the next write into that
// folder removes this machine's dead writers' files on commit, and leaves
// files named before the tag (which a shared folder's other machines may
// have written) and everything else.
TEST(AtomicFile, ACommitRemovesDeadWritersTemporaryFiles)
{
  testing::ScratchFolder folder;
  const std::string tag = writerTagOfThisProcess(folder.path());
  const std::string gone = std::to_string(aProcessThatIsGone());
  const auto leftover = folder / (".big.tmp-" + tag + "-" + gone + "-1.obj");
  const auto anotherFiles = folder / (".small.tmp-" + tag + "-" + gone + "-1.obj");
  const auto untagged = folder / (".big.tmp-" + gone + "-2.obj");
  for (const auto& path : {leftover, anotherFiles, untagged}) std::ofstream(path) << "x";
  AtomicFile file(folder / "big.obj");
  file.open() << "o";
  file.commit();
  EXPECT_FALSE(std::filesystem::exists(leftover));
  EXPECT_FALSE(std::filesystem::exists(anotherFiles));
  EXPECT_TRUE(std::filesystem::exists(untagged));
  EXPECT_TRUE(std::filesystem::exists(folder / "big.obj"));
}

// The first Ctrl-C is a request, and the job unwinds, removing its temporary
// files; a second one ends the process at once, without unwinding: the
// signal handler itself must remove the temporary files of writes under way.
TEST(AtomicFileDeathTest, ASecondCtrlCEndsTheProcessAndLeavesNoTemporaryFile)
{
  testing::ScratchFolder folder;
  EXPECT_EXIT(
      {
        interrupt::installHandler();
        AtomicFile first(folder / "a.obj");
        AtomicFile second(folder / "b.glb");
        std::raise(SIGINT);  // the request: the process goes on
        if (!interrupt::requested() || !std::filesystem::exists(first.temporaryPath())) std::_Exit(3);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));  // a person's second Ctrl-C
        std::raise(SIGINT);                                           // ends it
        std::_Exit(4);
      },
      ::testing::KilledBySignal(SIGINT), "");
  EXPECT_TRUE(folder.entries().empty()) << ::testing::PrintToString(folder.entries());
}

// coreutils' `timeout -s INT` sends the signal to the process and then to
// its process group: the copy that follows at once is the same request, and
// the job still unwinds and says what is complete.
TEST(AtomicFileDeathTest, ACopyOfTheFirstSignalAtOnceIsTheSameRequest)
{
  testing::ScratchFolder folder;
  EXPECT_EXIT(
      {
        interrupt::installHandler();
        AtomicFile file(folder / "a.obj");
        std::raise(SIGINT);
        std::raise(SIGINT);  // at once: the same request
        std::_Exit(interrupt::requested() && std::filesystem::exists(file.temporaryPath()) ? 7 : 3);
      },
      ::testing::ExitedWithCode(7), "");
}

// A writer opens the temporary file the constructor made; if it has gone
// (the last-resort handler removed it while the content was being built),
// the write fails instead of making it again.
TEST(AtomicFile, AWriterNeverMakesTheTemporaryFileAgain)
{
  testing::ScratchFolder folder;
  const TriangleMesh mesh = testing::icosphere(1);
  for (const auto& [name, write] : std::vector<std::pair<std::string, std::function<void(const AtomicFile&)>>>{
           {"a.obj", [&](const AtomicFile& f) { writeObj(mesh, f); }},
           {"a.glb", [&](const AtomicFile& f) { writeGltf(mesh, MeshFormat::Glb, f); }},
           {"a.ply", [&](const AtomicFile& f) { writeWithOpenMesh(mesh, MeshFormat::Ply, f); }}}) {
    AtomicFile file(folder / name);
    std::filesystem::remove(file.temporaryPath());
    EXPECT_THROW(write(file), OutputError) << name;
    EXPECT_FALSE(std::filesystem::exists(file.temporaryPath())) << name;
  }
}

// The handler runs on one thread while the others go on writing: once it has
// removed the listed files, no other thread may make a new one, or it stays
// (LastResort.AnAbortInTheMiddleOfAMorphLeavesNoPartialFile, now and then).
TEST(AtomicFileDeathTest, NoTemporaryFileIsMadeAfterTheHandlerHasRemovedThem)
{
  testing::ScratchFolder folder;
  EXPECT_EXIT(
      {
        std::atomic<int> made{0};
        std::thread writer([&] {
          std::vector<std::unique_ptr<AtomicFile>> open;  // kept: each one stays until the process ends
          for (int i = 0;; ++i) {
            if (open.size() == 24) open.erase(open.begin());
            open.push_back(std::make_unique<AtomicFile>(folder / ("frame_" + std::to_string(i) + ".obj")));
            made.fetch_add(1);
          }
        });
        while (made.load() < 100) std::this_thread::yield();
        temporary_files::removeAllFromSignalHandler();
        // A writer that went on would have made many files in this time.
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        const bool clean = folder.entries().empty();
        std::_Exit(clean ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace lbmshape
