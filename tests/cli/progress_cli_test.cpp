// Long stages of a denoise run show how far they are on stderr, never on
// stdout, and Ctrl-C stops a long run without leaving a file behind.
#include <signal.h>
#include <spawn.h>
#include <fcntl.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

extern char** environ;

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

bool hasLineStartingWith(const std::string& text, const std::string& start)
{
  for (const auto& line : testing::nonEmptyLines(text))
    if (line.find(start) != std::string::npos) return true;
  return false;
}

class DenoiseProgress : public ::testing::Test {
protected:
  void SetUp() override
  {
    input = (folder / "sphere.obj").string();
    writeMesh(testing::icosphere(3), input);
  }
  void TearDown() override
  {
    unsetenv("LBMSHAPE_PROGRESS_MS");
    unsetenv("LBMSHAPE_DEVICE_TRACE");
  }
  testing::ScratchFolder folder;
  std::string input;
};

// LBMSHAPE_DEVICE_TRACE=1 lists every compute submission on stderr, in
// order, with what it does and its device time; without it there is no
// such line.
TEST_F(DenoiseProgress, TheDeviceTraceListsEachSubmission)
{
  const fs::path output = folder / "out.glb";
  const std::vector<std::string> args = {"denoise", input, output.string(), "--res", "32", "--json"};
  setenv("LBMSHAPE_DEVICE_TRACE", "1", 1);
  const testing::CliResult traced = testing::runLbmshape(args);
  ASSERT_EQ(traced.exitCode, 0) << traced.err;
  for (const char* n : {"1", "2", "3"})
    EXPECT_TRUE(hasLineStartingWith(traced.err, std::string("lbmshape: device trace: submission ") + n + " "))
        << traced.err;
  EXPECT_NE(traced.err.find(" ms waited"), std::string::npos) << traced.err;
  // Each names the work it does: the band's steps are among them.
  EXPECT_NE(traced.err.find("(band steps) at "), std::string::npos) << traced.err;
  EXPECT_NO_THROW(nlohmann::json::parse(traced.out)) << "stdout holds only the JSON result: " << traced.out;
  unsetenv("LBMSHAPE_DEVICE_TRACE");
  const testing::CliResult plain = testing::runLbmshape(args);
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_EQ(plain.err.find("device trace"), std::string::npos) << plain.err;
}

TEST_F(DenoiseProgress, StagesShowHowFarTheyAreOnStderrOnly)
{
  setenv("LBMSHAPE_PROGRESS_MS", "0", 1);  // every stage is "long"
  const fs::path output = folder / "out.glb";
  testing::CliResult r =
      testing::runLbmshape({"denoise", input, output.string(), "--res", "48", "--steps", "200", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(hasLineStartingWith(r.err, "lbmshape: lbm ")) << r.err;
  EXPECT_TRUE(hasLineStartingWith(r.err, "% (steps)")) << r.err;
  EXPECT_TRUE(hasLineStartingWith(r.err, "lbmshape: sdf ")) << r.err;
  EXPECT_NO_THROW(nlohmann::json::parse(r.out)) << "stdout holds only the JSON result: " << r.out;

  testing::CliResult quiet =
      testing::runLbmshape({"-q", "denoise", input, output.string(), "--res", "48", "--steps", "50"});
  ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}

TEST_F(DenoiseProgress, CtrlCStopsALongRunAndWritesNothing)
{
  const fs::path output = folder / "out.glb";
  std::vector<std::string> args = {
      testing::lbmshapeBinary(), "denoise", input, output.string(), "--res", "64", "--steps", "1000000"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  setenv("LBMSHAPE_PROGRESS_MS", "0", 1);  // a progress line says the steps have started
  const fs::path log = folder / "stderr.txt";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  auto stepping = [&] {
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return text.find("(steps)") != std::string::npos;
  };
  while (!stepping() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  // Stopped between step batches, not after the million steps.
  std::ifstream in(log);
  const std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string stopped = "interrupted: after ";
  const size_t at = err.find(stopped);
  ASSERT_NE(at, std::string::npos) << err;
  EXPECT_LT(std::stol(err.substr(at + stopped.size())), 1000000) << err;
  for (const auto& entry : fs::directory_iterator(folder.path()))
    EXPECT_TRUE(entry.path() == log || entry.path().filename() == "sphere.obj")
        << "nothing written, no temporary file: " << entry.path();
}

}  // namespace
}  // namespace lbmshape
