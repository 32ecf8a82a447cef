// SIGTERM (kill, timeout, a batch scheduler) and SIGHUP (a closed terminal)
// stop lbmshape as Ctrl-C does: at a random moment of a morph or a denoise,
// the process ends with 128 + the signal's number (or finished first, or
// died of the signal before its handler was set), and the folder holds only
// complete files: no hidden temporary file, no partial mesh.
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/core/address_sanitizer.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

struct SignalCase {
  const char* name;
  int signal;
  bool morph;
};

void PrintTo(const SignalCase& c, std::ostream* os) { *os << c.name; }

class StopSignal : public ::testing::TestWithParam<SignalCase> {};

// Every file below `folder`, other than the inputs, is a complete mesh.
void expectOnlyCompleteFiles(const fs::path& folder, int attempt)
{
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name == "a.obj" || name == "b.obj" || entry.is_directory()) continue;
    EXPECT_NE(name[0], '.') << "attempt " << attempt << ": a temporary file was left: " << entry.path();
    EXPECT_NO_THROW(readMesh(entry.path())) << "attempt " << attempt << ": " << entry.path();
  }
}

TEST_P(StopSignal, LeavesOnlyCompleteFilesAndSaysWhichSignal)
{
  const SignalCase& c = GetParam();
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "a.obj");
  writeMesh(testing::torusMesh(0.8, 0.3, 32, 16), folder / "b.obj");
  std::mt19937 random(uint32_t(c.signal * 7 + c.morph));  // the same moments on every run of the suite
  std::uniform_int_distribution<int> delayMs(0, 600);
  int handled = 0;
  for (int attempt = 0; attempt < 20; ++attempt) {
    const fs::path out = folder / ("out" + std::to_string(attempt));
    std::vector<std::string> args =
        c.morph ? std::vector<std::string>{"morph",
                                           (folder / "a.obj").string(),
                                           (folder / "b.obj").string(),
                                           out.string(),
                                           "--res",
                                           "40",
                                           "--frames",
                                           "60",
                                           "--format",
                                           "obj"}
                : std::vector<std::string>{
                      "denoise", (folder / "a.obj").string(), (out.string() + ".glb"), "--res", "64", "--steps", "60"};
    const pid_t pid = testing::spawnLbmshape(args);
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(delayMs(random)));
    kill(pid, c.signal);
    const int status = testing::waitForExit(pid, std::chrono::seconds(30));
    if (WIFSIGNALED(status)) {
      EXPECT_EQ(WTERMSIG(status), c.signal) << "attempt " << attempt << ": only before the handler is set";
    } else {
      ASSERT_TRUE(WIFEXITED(status));
      const int code = WEXITSTATUS(status);
      EXPECT_TRUE(code == 0 || code == 128 + c.signal) << "attempt " << attempt << ": exit " << code;
      handled += code == 128 + c.signal;
    }
    expectOnlyCompleteFiles(folder.path(), attempt);
  }
  EXPECT_GE(handled, 5) << "most signals should land while the job runs";
}

INSTANTIATE_TEST_SUITE_P(Cases, StopSignal,
                         ::testing::Values(SignalCase{"sigterm_morph", SIGTERM, true},
                                           SignalCase{"sighup_morph", SIGHUP, true},
                                           SignalCase{"sigterm_denoise", SIGTERM, false},
                                           SignalCase{"sighup_denoise", SIGHUP, false}),
                         [](const auto& info) { return std::string(info.param.name); });

// What the message says matches what the folder holds.
TEST(StopSignal, TheMessageCountsTheFramesTheFolderHolds)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "a.obj");
  writeMesh(testing::torusMesh(0.8, 0.3, 32, 16), folder / "b.obj");
  const fs::path out = folder / "frames", log = folder / "stderr.txt";
  const pid_t pid =
      testing::spawnLbmshape({"-q", "morph", (folder / "a.obj").string(), (folder / "b.obj").string(), out.string(),
                              "--res", "48", "--frames", "400", "--format", "obj", "--no-animation"},
                             log.string());
  ASSERT_GT(pid, 0);
  testing::waitForFile(out / "frame_0004.obj", std::chrono::seconds(60));
  kill(pid, SIGTERM);
  const int status = testing::waitForExit(pid, std::chrono::seconds(30));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143);
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(out)) frames += entry.path().extension() == ".obj";
  std::ifstream in(log);
  const std::string message((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(message.find("terminated (SIGTERM): " + std::to_string(frames) + " complete frames"), std::string::npos)
      << frames << " frames; " << message;
}

// A rerun with --force that is stopped leaves the earlier morph's files as
// they were (its new frames are made in a hidden folder, which goes); before,
// the earlier files were removed first and neither set was left whole.
TEST(StopSignal, AStoppedRerunWithForceKeepsTheEarlierMorph)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "a.obj");
  writeMesh(testing::torusMesh(0.8, 0.3, 32, 16), folder / "b.obj");
  const fs::path out = folder / "frames", log = folder / "stderr.txt";
  const std::vector<std::string> morph = {
      "-q",       "morph", (folder / "a.obj").string(), (folder / "b.obj").string(), out.string(), "--res", "24",
      "--format", "obj"};
  std::vector<std::string> first = morph;
  first.insert(first.end(), {"--frames", "3"});
  ASSERT_EQ(testing::runLbmshape(first).exitCode, 0);
  const auto contents = [&] {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(out)) {
      std::ifstream in(entry.path(), std::ios::binary);
      files[entry.path().filename().string()] =
          std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }
    return files;
  };
  const auto earlier = contents();
  ASSERT_EQ(earlier.size(), 4u);  // three frames and morph.glb

  std::vector<std::string> rerun = morph;
  rerun[6] = "40";
  rerun.insert(rerun.end(), {"--frames", "400", "--no-animation", "--force"});
  const pid_t pid = testing::spawnLbmshape(rerun, log.string());
  ASSERT_GT(pid, 0);
  testing::waitForFile(out / ".lbmshape-new-frames" / "frame_0004.obj", std::chrono::seconds(60));
  kill(pid, SIGTERM);
  const int status = testing::waitForExit(pid, std::chrono::seconds(30));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_EQ(contents(), earlier) << "the earlier morph's files, and nothing else";
  std::ifstream in(log);
  const std::string message((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(message.find("not kept: " + out.string() + " keeps the earlier morph's files"), std::string::npos)
      << message;
}

// A jobs file stopped in its second job still reports, with --json, the
// job done and the one stopped, so that a script can run the rest; the
// message says how many were done.
TEST(StopSignal, AStoppedJobsFileReportsTheJobsDone)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "a.obj");
  writeMesh(testing::torusMesh(0.8, 0.3, 32, 16), folder / "b.obj");
  const nlohmann::json jobs =
      nlohmann::json::array({{{"command", "denoise"}, {"input", "a.obj"}, {"output", "a.glb"}, {"res", 24}},
                             {{"command", "morph"},
                              {"source", "a.obj"},
                              {"target", "b.obj"},
                              {"output", "frames"},
                              {"res", 48},
                              {"frames", 400},
                              {"format", "obj"},
                              {"no-animation", true}},
                             {{"command", "denoise"}, {"input", "b.obj"}, {"output", "b.glb"}, {"res", 24}}});
  std::ofstream(folder / "jobs.json") << jobs.dump();
  const fs::path log = folder / "stderr.txt", out = folder / "stdout.json";
  const pid_t pid =
      testing::spawnLbmshape({"-q", "run", (folder / "jobs.json").string(), "--json"}, log.string(), out.string());
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(testing::waitForFile(folder / "frames" / "frame_0004.obj", std::chrono::seconds(60)));
  kill(pid, SIGTERM);
  const int status = testing::waitForExit(pid, std::chrono::seconds(30));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143);
  std::ifstream in(out);
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report["interrupted"], true);
  EXPECT_EQ(report["run"], 2);
  EXPECT_EQ(report["failed"], 1) << "the job stopped is counted as failed, as its \"ok\" says";
  ASSERT_EQ(report["results"].size(), 2u);
  EXPECT_EQ(report["results"][0]["ok"], true);
  EXPECT_EQ(report["results"][1]["ok"], false);
  EXPECT_EQ(report["results"][1]["exit_code"], 143);
  EXPECT_EQ(report["results"][1]["error"].get<std::string>().rfind("terminated (SIGTERM): ", 0), 0u)
      << report["results"][1]["error"];
  EXPECT_FALSE(fs::exists(folder / "b.glb"));
  std::ifstream logIn(log);
  const std::string message((std::istreambuf_iterator<char>(logIn)), std::istreambuf_iterator<char>());
  EXPECT_NE(message.find("; 1 of 3 jobs done"), std::string::npos) << message;
}

// A library that aborts the process (Mesa's LLVM, out of memory while
// compiling a shader) ends it like an error: one line, exit 5, and no
// temporary file or new empty folder left. Sanitized builds keep the
// default abort, so that a sanitizer's report is never taken for one.
TEST(LastResort, AnAbortInTheMiddleOfAMorphLeavesNoPartialFile)
{
  if (builtWithAddressSanitizer) GTEST_SKIP() << "a build with AddressSanitizer keeps the default SIGABRT";
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "a.obj");
  writeMesh(testing::torusMesh(0.8, 0.3, 32, 16), folder / "b.obj");
  const fs::path out = folder / "new" / "frames", log = folder / "stderr.txt";
  const pid_t pid = testing::spawnLbmshape(
      {"-q", "morph", (folder / "a.obj").string(), (folder / "b.obj").string(), out.string(), "--res", "48", "--frames",
       "400", "--steps-per-frame", "1", "--format", "obj", "--no-animation"},
      log.string());
  ASSERT_GT(pid, 0);
  testing::waitForFile(out / "frame_0002.obj", std::chrono::seconds(60));
  kill(pid, SIGABRT);
  const int status = testing::waitForExit(pid, std::chrono::seconds(30));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 5);
  std::ifstream in(log);
  const std::string message((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(testing::nonEmptyLines(message).size(), 1u) << message;
  EXPECT_NE(message.find("lbmshape: error: aborted by a library"), std::string::npos) << message;
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_NE(entry.path().filename().string()[0], '.') << "a temporary file was left: " << entry.path();
}

TEST(LastResort, AnAbortBeforeTheFirstFrameLeavesNoNewFolder)
{
  if (builtWithAddressSanitizer) GTEST_SKIP() << "a build with AddressSanitizer keeps the default SIGABRT";
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(5), folder / "a.obj");
  writeMesh(testing::torusMesh(0.8, 0.3, 96, 48), folder / "b.obj");
  const fs::path top = folder / "new", out = top / "deeper" / "frames";
  const pid_t pid = testing::spawnLbmshape({"-q", "morph", (folder / "a.obj").string(), (folder / "b.obj").string(),
                                            out.string(), "--res", "160", "--frames", "4", "--no-animation"});
  ASSERT_GT(pid, 0);
  // The folder is made once both fields are known; the first frame takes
  // the lattice's first steps longer.
  testing::waitForFile(out, std::chrono::seconds(60));
  kill(pid, SIGABRT);
  const int status = testing::waitForExit(pid, std::chrono::seconds(30));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 5);
  // Either the first frame was complete (it is kept, nothing temporary
  // beside it) or the new folders, all of them, went.
  if (fs::exists(out / "frame_0000.glb")) {
    for (const auto& entry : fs::directory_iterator(out))
      EXPECT_NE(entry.path().filename().string()[0], '.') << "a temporary file was left: " << entry.path();
  } else {
    EXPECT_FALSE(fs::exists(top)) << "an empty new folder was left";
  }
}

// A stop is honoured inside the signed distance too, between chunks of its
// work, not only when the stage ends: stopped during its first part (the
// exact band), a denoise never starts the next (the far field). The CPU's
// parts, so --sdf cpu: on a GPU the distances are the device's, whose
// chunks DeviceBandDistancesInterrupted stops.
TEST(StopSignal, TheSignedDistanceStopsWithinItsPart)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(6), folder / "a.obj");
  const fs::path log = folder / "stderr.txt";
  setenv("LBMSHAPE_PROGRESS_MS", "0", 1);  // every part of the stage says when it starts
  const pid_t pid = testing::spawnLbmshape(
      {"denoise", (folder / "a.obj").string(), (folder / "out.glb").string(), "--res", "640", "--sdf", "cpu"},
      log.string());
  unsetenv("LBMSHAPE_PROGRESS_MS");
  ASSERT_GT(pid, 0);
  auto text = [&] {
    std::ifstream in(log);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (text().find("(exact band)") == std::string::npos && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const bool inThePart = text().find("(exact band)") != std::string::npos;
  kill(pid, SIGTERM);
  const int status = testing::waitForExit(pid, std::chrono::seconds(60));
  ASSERT_TRUE(inThePart) << "the stage never said it began the exact band: " << text();
  ASSERT_TRUE(WIFEXITED(status)) << text();
  EXPECT_EQ(WEXITSTATUS(status), 143) << text();
  EXPECT_EQ(text().find("(far field)"), std::string::npos) << "it went on to the next part: " << text();
  EXPECT_NE(text().find("terminated (SIGTERM): nothing was written"), std::string::npos) << text();
  EXPECT_FALSE(fs::exists(folder / "out.glb"));
}

// A signal the parent ignores stays ignored: under `nohup` a hang-up must
// not stop the job.
TEST(StopSignal, AnIgnoredHangUpStaysIgnored)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "a.obj");
  writeMesh(testing::torusMesh(0.8, 0.3, 32, 16), folder / "b.obj");
  const fs::path out = folder / "frames";
  struct sigaction ignore = {}, previous = {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGHUP, &ignore, &previous);  // inherited by the child, as nohup does
  const pid_t pid =
      testing::spawnLbmshape({"-q", "morph", (folder / "a.obj").string(), (folder / "b.obj").string(), out.string(),
                              "--res", "32", "--frames", "12", "--format", "obj", "--no-animation"});
  sigaction(SIGHUP, &previous, nullptr);
  ASSERT_GT(pid, 0);
  testing::waitForFile(out / "frame_0001.obj", std::chrono::seconds(60));
  kill(pid, SIGHUP);
  const int status = testing::waitForExit(pid, std::chrono::seconds(60));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the hang-up was ignored and the morph finished";
  EXPECT_TRUE(fs::exists(out / "frame_0011.obj"));
}

}  // namespace
}  // namespace lbmshape
