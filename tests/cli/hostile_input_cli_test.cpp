// The whole program on hostile input, as a service running it on uploaded
// files would: every malformed mesh, read by `compare` and by `denoise`
// under a 4 GB address-space limit, ends with exit 3, one error line and
// nothing written; and when memory does run out, or stdout cannot be
// written, the exit code says so (5, 4) instead of a signal.
#include <sys/wait.h>

#include <algorithm>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_file_cases.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;
using testing::MeshFileCase;

void writeBytes(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

constexpr size_t fourGigabytes = 4096;

class HostileFileCli : public ::testing::TestWithParam<MeshFileCase> {
protected:
  void SetUp() override
  {
    LBMSHAPE_SKIP_WITHOUT_ADDRESS_SPACE_LIMITS();
    input_ = folder_ / (GetParam().name + GetParam().extension);
    writeBytes(input_, GetParam().bytes());
    writeMesh(testing::box({0, 0, 0}, {1, 1, 1}), folder_ / "cube.obj");
    fs::create_directory(folder_ / "out");
  }

  void expectRefused(const testing::CliResult& result)
  {
    EXPECT_EQ(result.exitCode, 3) << result.err;
    const auto lines = testing::messageLines(result.err);
    ASSERT_EQ(lines.size(), 1u) << result.err;
    EXPECT_EQ(lines[0].rfind("lbmshape: error: cannot read " + input_.string(), 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(GetParam().refusal), std::string::npos) << lines[0];
    EXPECT_TRUE(fs::is_empty(folder_ / "out")) << "nothing written";
  }

  testing::ScratchFolder folder_;
  fs::path input_;
};

// What only a grid cannot hold (parts a million times their size apart:
// flat on any grid) compare measures, as it does a flat mesh; the rest it
// refuses as denoise does.
bool onlyAGridCannotHold(const MeshFileCase& c) { return c.refusal.find("flat on any grid") != std::string::npos; }

TEST_P(HostileFileCli, CompareRefusesIt)
{
  const auto result =
      testing::runLbmshapeWithin(fourGigabytes, {"compare", input_.string(), (folder_ / "cube.obj").string(), "-q"});
  if (onlyAGridCannotHold(GetParam())) {
    EXPECT_EQ(result.exitCode, 0) << result.err;
    return;
  }
  expectRefused(result);
}

TEST_P(HostileFileCli, DenoiseRefusesIt)
{
  expectRefused(testing::runLbmshapeWithin(
      fourGigabytes, {"denoise", input_.string(), (folder_ / "out" / "out.glb").string(), "--res", "24", "-q"}));
}

INSTANTIATE_TEST_SUITE_P(Cases, HostileFileCli, ::testing::ValuesIn(testing::hostileMeshFiles()),
                         [](const auto& info) { return info.param.name; });

TEST(MemoryPressure, CompareEndsWithItsResultOrOutOfMemoryNeverASignal)
{
  LBMSHAPE_SKIP_WITHOUT_ADDRESS_SPACE_LIMITS();
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(6), folder / "a.obj");
  writeMesh(testing::icosphere(6, 1.01), folder / "b.obj");
  for (size_t megabytes : {60, 100, 150, 250}) {
    const auto result = testing::runLbmshapeWithin(
        megabytes, {"compare", (folder / "a.obj").string(), (folder / "b.obj").string(), "-q"});
    EXPECT_TRUE(result.exitCode == 0 || result.exitCode == 5) << megabytes << " MB: exit " << result.exitCode << "\n"
                                                              << result.err;
    if (result.exitCode == 5) {
      // Refused up front where its samples would not fit, else out of memory.
      EXPECT_EQ(testing::nonEmptyLines(result.err).size(), 1u) << result.err;
      EXPECT_TRUE(result.err.find("lbmshape: error: out of memory") != std::string::npos ||
                  result.err.find("lbmshape: error: comparing with") != std::string::npos)
          << result.err;
    }
  }
}

TEST(MemoryPressure, AMorphEndsWellAndLeavesNoEmptyFolder)
{
  LBMSHAPE_SKIP_WITHOUT_ADDRESS_SPACE_LIMITS();
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "a.obj");
  writeMesh(testing::box({-0.8, -0.8, -0.8}, {0.8, 0.8, 0.8}), folder / "b.obj");
  for (size_t megabytes : {150, 300, 500, 800}) {
    // Two folders deep, both new: a failed morph removes both.
    const fs::path frames = folder / ("run" + std::to_string(megabytes)) / "frames";
    const auto result =
        testing::runLbmshapeWithin(megabytes, {"morph", (folder / "a.obj").string(), (folder / "b.obj").string(),
                                               frames.string(), "--res", "48", "--frames", "6", "-q"});
    EXPECT_TRUE(result.exitCode == 0 || result.exitCode == 5) << megabytes << " MB: exit " << result.exitCode << "\n"
                                                              << result.err;
    if (result.exitCode == 5) {
      // One error line (the tests run with the validation layer on, whose
      // warnings about the failed allocation may come before it).
      const auto lines = testing::nonEmptyLines(result.err);
      EXPECT_EQ(std::count_if(lines.begin(), lines.end(),
                              [](const std::string& l) { return l.rfind("lbmshape: error: ", 0) == 0; }),
                1)
          << result.err;
    }
    EXPECT_EQ(fs::exists(frames.parent_path()), fs::exists(frames))
        << megabytes << " MB: an empty parent was left behind";
    if (fs::exists(frames)) {
      EXPECT_FALSE(fs::is_empty(frames)) << megabytes << " MB: an empty folder was left behind";
      for (const auto& entry : fs::directory_iterator(frames))
        EXPECT_NE(entry.path().filename().string()[0], '.') << "a temporary file was left: " << entry.path();
    }
  }
}

// The CPU reference solver's memory is the host's: a job it cannot hold is
// refused before any allocation, with what it needs and what grid would
// fit, under an address-space limit as on a small machine.
TEST(MemoryPressure, TheReferenceSolverRefusesAJobTheHostCannotHold)
{
  LBMSHAPE_SKIP_WITHOUT_ADDRESS_SPACE_LIMITS();
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "a.obj");
  const std::string a = (folder / "a.obj").string();
  for (std::vector<std::string> args :
       {std::vector<std::string>{"--device", "reference", "denoise", a, (folder / "out.glb").string(), "--res", "400",
                                 "--dense"},
        {"--device", "reference", "denoise", a, (folder / "out.glb").string(), "--res", "1000"},
        {"--device", "reference", "morph", a, a, (folder / "frames").string(), "--res", "400"}}) {
    const auto result = testing::runLbmshapeWithin(1000, args);
    EXPECT_EQ(result.exitCode, 5) << args[4] << "\n" << result.err;
    const auto lines = testing::messageLines(result.err);
    ASSERT_EQ(lines.size(), 1u) << result.err;
    EXPECT_NE(lines[0].find("needs about"), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("would fit"), std::string::npos) << lines[0];
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.obj"}) << "nothing written";
  }
}

// Where the Vulkan device is the CPU (lavapipe), its memory is the host's:
// a band the host cannot hold beside the driver is refused before the
// lattice is made, with a --res that does fit (it used to fail inside the
// driver, "vkAllocateMemory: ErrorOutOfDeviceMemory", or crash in LLVM
// compiling under `ulimit -v 400000`; glibc's arenas alone reserved 500 MB
// of address space).
TEST(MemoryPressure, ACpuDeviceRefusesABandTheHostCannotHoldNamingAResThatFits)
{
  LBMSHAPE_SKIP_WITHOUT_ADDRESS_SPACE_LIMITS();
  const nlohmann::json info = nlohmann::json::parse(testing::runLbmshape({"info", "--json"}).out);
  if (info["devices"][info["selected"].get<size_t>()]["type"] != "cpu")
    GTEST_SKIP() << "the default Vulkan device has memory of its own";
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(4), folder / "a.obj");
  const std::string a = (folder / "a.obj").string(), out = (folder / "out.glb").string();
  const size_t megabytes = 700;
  const auto refused = testing::runLbmshapeWithin(megabytes, {"denoise", a, out, "--res", "400", "-q"});
  EXPECT_EQ(refused.exitCode, 5) << refused.err;
  const auto lines = testing::messageLines(refused.err);
  ASSERT_EQ(lines.size(), 1u) << refused.err;
  EXPECT_NE(lines[0].find("the narrow band of"), std::string::npos) << lines[0];
  std::smatch fits;
  ASSERT_TRUE(std::regex_search(lines[0], fits, std::regex(R"(\(--res ([0-9]+)\) would fit)"))) << lines[0];
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.obj"}) << "nothing written";
  const auto suggested = testing::runLbmshapeWithin(megabytes, {"denoise", a, out, "--res", fits[1].str(), "-q"});
  EXPECT_EQ(suggested.exitCode, 0) << "--res " << fits[1].str() << ": " << suggested.err;
}

TEST(MemoryPressure, AnAnimationThatCannotFitIsRefusedBeforeAnyWorkSayingWhatWould)
{
  LBMSHAPE_SKIP_WITHOUT_ADDRESS_SPACE_LIMITS();
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "a.obj");
  writeMesh(testing::box({-0.8, -0.8, -0.8}, {0.8, 0.8, 0.8}), folder / "b.obj");
  // 100,000 frames of a sphere 90 voxels across: hundreds of GB of meshes.
  // A plain morph.glb is streamed to its file; a compressed one, and the
  // preview's frames, are held in memory.
  for (const std::string heldInMemory : {"--compress", "--preview"}) {
    std::vector<std::string> args = {"morph",
                                     (folder / "a.obj").string(),
                                     (folder / "b.obj").string(),
                                     (folder / "frames").string(),
                                     "--res",
                                     "96",
                                     "--frames",
                                     "100000",
                                     heldInMemory};
    if (heldInMemory == "--preview") args.push_back((folder / "sheet.png").string());
    const auto result = testing::runLbmshapeWithin(1000, args);
    EXPECT_EQ(result.exitCode, 5) << heldInMemory << "\n" << result.err;
    const auto lines = testing::messageLines(result.err);
    ASSERT_EQ(lines.size(), 1u) << result.err;
    EXPECT_NE(lines[0].find(std::string("the 100000 frames of ") +
                            (heldInMemory == "--preview" ? "the preview" : "a compressed morph.glb") + " need about"),
              std::string::npos)
        << lines[0];
    EXPECT_NE(lines[0].find("frames would fit, or leave out " + heldInMemory), std::string::npos) << lines[0];
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"a.obj", "b.obj"})) << "nothing written";
  }
}

TEST(StandardOutput, ResultsThatCannotBeWrittenAreAnOutputError)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(1), folder / "a.obj");
  const auto result =
      testing::runLbmshape({"compare", (folder / "a.obj").string(), (folder / "a.obj").string(), "--json"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  // runLbmshape sends stdout to a file; /dev/full is the disk that is always full.
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "'" + std::string.
  const std::string mesh = (folder / "a.obj").string();
  std::string command(1, '\'');
  for (const std::string& piece : {testing::lbmshapeBinary(), std::string("' compare '"), mesh, std::string("' '"),
                                   mesh, std::string("' --json >/dev/full 2>/dev/null")})
    command += piece;
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 4);
}

TEST(JobsFileInput, NestedWithoutBoundIsAnInputErrorNotAStackOverflow)
{
  testing::ScratchFolder folder;
  writeBytes(folder / "jobs.json", std::string(100000, '[') + std::string(100000, ']'));
  const auto result = testing::runLbmshape({"run", (folder / "jobs.json").string()});
  EXPECT_EQ(result.exitCode, 3) << result.err;
  EXPECT_NE(result.err.find("nests more than"), std::string::npos) << result.err;
}

TEST(JobsFileInput, ANumberBeyondADoubleIsAnInputError)
{
  testing::ScratchFolder folder;
  writeBytes(folder / "jobs.json", R"([{"command": "denoise", "input": "a.obj", "output": "b.obj", "gamma": 1e999}])");
  const auto result = testing::runLbmshape({"run", (folder / "jobs.json").string()});
  EXPECT_EQ(result.exitCode, 3) << result.err;
  EXPECT_NE(result.err.find("out of range"), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("internal error"), std::string::npos) << result.err;
}

TEST(JobsFileInput, AFolderIsAnInputError)
{
  testing::ScratchFolder folder;
  const auto result = testing::runLbmshape({"run", folder.path().string()});
  EXPECT_EQ(result.exitCode, 3) << result.err;
  EXPECT_NE(result.err.find("it is a folder"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace lbmshape
