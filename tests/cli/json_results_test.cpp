// The --json results that scripts rely on: one object on stdout, with the
// keys the documentation promises, and values that make sense together.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>

#include <sys/stat.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"
#include "support/scratch_folder.hpp"

namespace lbmshape {
namespace {

nlohmann::json parseStdout(const testing::CliResult& r)
{
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(r.out);  // throws, failing the test, unless it is exactly one JSON document
}

TEST(JsonResults, InfoListsDevicesAndTheSelectedOne)
{
  auto j = parseStdout(testing::runLbmshape({"info", "--json"}));
  ASSERT_FALSE(j["devices"].empty());
  int selected = 0;
  for (const auto& d : j["devices"]) {
    for (const char* key : {"index", "name", "type", "driver", "device_local_bytes", "max_storage_buffer_range"})
      EXPECT_TRUE(d.contains(key)) << key;
    selected += d["selected"].get<bool>();
  }
  EXPECT_EQ(selected, 1);
  EXPECT_TRUE(j["validation"].get<bool>()) << "tests run with the validation layer";
}

// info says where the stages with both paths run on the selected device
// (ComputeDevice's rule): auto takes the device on a GPU, the CPU on a CPU
// device and on the reference; a forced choice is taken as given, the
// device on the reference refused.
TEST(JsonResults, InfoSaysWhereTheDistancesAndTheFramesRun)
{
  auto j = parseStdout(testing::runLbmshape({"info", "--json"}));
  std::string type;
  for (const auto& d : j["devices"])
    if (d["selected"].get<bool>()) type = d["type"].get<std::string>();
  const std::string automatic = type == "cpu" ? "cpu" : "device";
  EXPECT_EQ(j["sdf_on"], automatic);
  EXPECT_EQ(j["extract_on"], automatic);
  j = parseStdout(testing::runLbmshape({"info", "--json", "--sdf", "cpu", "--extract", "device"}));
  EXPECT_EQ(j["sdf_on"], "cpu");
  EXPECT_EQ(j["extract_on"], "device");
  j = parseStdout(testing::runLbmshape({"info", "--json", "--device", "reference"}));
  EXPECT_EQ(j["sdf_on"], "cpu");
  EXPECT_EQ(j["extract_on"], "cpu");
  const testing::CliResult refused = testing::runLbmshape({"info", "--extract", "device", "--device", "reference"});
  EXPECT_EQ(refused.exitCode, 2) << refused.err;
  EXPECT_NE(refused.err.find("--extract device needs a Vulkan device"), std::string::npos) << refused.err;
  const testing::CliResult text = testing::runLbmshape({"info", "--extract", "cpu"});
  EXPECT_NE(text.out.find("morph frames extracted on: cpu (--extract)"), std::string::npos) << text.out;
}

// lbmshape starts itself again with OpenMP's idle threads waiting
// passively, unless the user chose how they wait.
TEST(JsonResults, InfoShowsOpenMpThreadsWaitPassivelyUnlessTheUserChose)
{
  const std::string inherited = std::getenv("OMP_WAIT_POLICY") ? std::getenv("OMP_WAIT_POLICY") : "";
  unsetenv("OMP_WAIT_POLICY");
  const auto chosenByLbmshape = parseStdout(testing::runLbmshape({"info", "--json"}));
  setenv("OMP_WAIT_POLICY", "active", 1);
  const auto chosenByTheUser = parseStdout(testing::runLbmshape({"info", "--json"}));
  if (inherited.empty())
    unsetenv("OMP_WAIT_POLICY");
  else
    setenv("OMP_WAIT_POLICY", inherited.c_str(), 1);
  EXPECT_EQ(chosenByLbmshape["openmp_wait_policy"], "passive");
  EXPECT_EQ(chosenByTheUser["openmp_wait_policy"], "active");
}

// lbmshape starts itself again with malloc asking for huge pages, unless
// the user's GLIBC_TUNABLES says otherwise (another tunable of theirs
// does not stop it) or an address-space limit is set.
TEST(JsonResults, InfoShowsMallocAsksForHugePagesUnlessTheUserChose)
{
  const char* old = std::getenv("GLIBC_TUNABLES");
  const std::string inherited = old ? old : "";
  auto infoWith = [](const char* tunables) {
    if (tunables)
      setenv("GLIBC_TUNABLES", tunables, 1);
    else
      unsetenv("GLIBC_TUNABLES");
    return parseStdout(testing::runLbmshape({"info", "--json"}));
  };
  const auto chosenByLbmshape = infoWith(nullptr);
  const auto besideAnotherTunable = infoWith("glibc.malloc.check=0");
  const auto refusedByTheUser = infoWith("glibc.malloc.hugetlb=0");
  unsetenv("GLIBC_TUNABLES");
  const testing::CliResult limited = testing::runLbmshapeWithin(8192, {"info", "--json"});
  if (old)
    setenv("GLIBC_TUNABLES", inherited.c_str(), 1);
  else
    unsetenv("GLIBC_TUNABLES");
  EXPECT_EQ(chosenByLbmshape["malloc_huge_pages"], true);
  EXPECT_EQ(besideAnotherTunable["malloc_huge_pages"], true);
  EXPECT_EQ(refusedByTheUser["malloc_huge_pages"], false);
  if (testing::addressSpaceLimitsWork()) {
    ASSERT_EQ(limited.exitCode, 0) << limited.err;
    EXPECT_EQ(parseStdout(limited)["malloc_huge_pages"], false);
  }
}

std::string selectedDeviceName()
{
  auto info = parseStdout(testing::runLbmshape({"info", "--json"}));
  for (const auto& d : info["devices"])
    if (d["selected"].get<bool>()) return d["name"].get<std::string>();
  return "";
}

// The whole denoise a bench times beside its lattice, on the grid of the
// bench's longest side, and its figures against the bench's own.
void expectDenoiseStages(const nlohmann::json& stages, int res, const char* kind, double benchMlups)
{
  EXPECT_EQ(stages["res"], res);
  EXPECT_EQ(stages["lattice"]["kind"], kind);
  const auto& ms = stages["ms"];
  for (const char* stage : {"sdf", "setup", "lbm", "extract"}) EXPECT_GE(ms[stage].get<double>(), 0.0) << stage;
  EXPECT_GE(stages["steps_run"].get<int>(), 2) << "the automatic steps, on a noisy sphere";
  const double share = stages["lattice_share"];
  EXPECT_NEAR(share, ms["lbm"].get<double>() / ms["total"].get<double>(), 1e-9);
  EXPECT_GT(share, 0.0);
  EXPECT_LT(share, 1.0);
  EXPECT_NEAR(stages["mlups_over_bench"].get<double>(), stages["mlups"].get<double>() / benchMlups, 1e-9);
}

TEST(JsonResults, BenchReportsConsistentFigures)
{
  auto j = parseStdout(testing::runLbmshape({"bench", "--json", "--size", "24,20,16", "--steps", "5", "--runs", "2"}));
  EXPECT_EQ(j["device"], selectedDeviceName());
  EXPECT_EQ(j["size"], (nlohmann::json{24, 20, 16}));
  EXPECT_EQ(j["steps"], 5);
  EXPECT_EQ(j["bytes_per_update"], 152);
  const double cells = 24 * 20 * 16;
  for (const char* backend : {"vulkan", "reference"}) {
    const auto& b = j[backend];
    ASSERT_TRUE(b.is_object()) << backend;
    EXPECT_GT(b["ms_per_step"].get<double>(), 0.0);
    EXPECT_NEAR(b["mlups"].get<double>(), cells / (b["ms_per_step"].get<double>() * 1e3),
                1e-6 * b["mlups"].get<double>());
  }
  EXPECT_NEAR(j["vulkan"]["gbps"].get<double>(), j["vulkan"]["mlups"].get<double>() * 152e-3, 1e-6);
  EXPECT_NEAR(j["vulkan_over_reference"].get<double>(),
              j["vulkan"]["mlups"].get<double>() / j["reference"]["mlups"].get<double>(), 1e-9);
  EXPECT_GT(j["roofline_fraction"].get<double>(), 0.0);
  EXPECT_LE(j["roofline_fraction"].get<double>(), 1.0);
  EXPECT_GT(j["memory_bandwidth"]["gbps"].get<double>(), 0.1);
  // The roofline is the measured bandwidth's, or the lattice's own where higher.
  EXPECT_NEAR(j["roofline_mlups"].get<double>(),
              std::max(j["memory_bandwidth"]["gbps"].get<double>(), j["vulkan"]["gbps"].get<double>()) / 152e-3,
              1e-6 * j["roofline_mlups"].get<double>());
  // Half a second of untimed steps before the runs (24x20x16 takes far less
  // than that a step).
  EXPECT_GE(j["vulkan"]["warmup_steps"].get<int>(), 1);
  EXPECT_EQ(j["reference"]["warmup_steps"], 0) << "a CPU's clocks need no warm-up";
  EXPECT_EQ(j["vulkan"]["steps_per_run"], 5);
  EXPECT_GE(j["reference"]["steps_per_run"].get<int>(), 1) << "runs of at most 0.4 s: fewer steps if slower";
  EXPECT_LE(j["reference"]["steps_per_run"].get<int>(), 5);
  expectDenoiseStages(j["denoise"], 24, "grid", j["vulkan"]["mlups"].get<double>());
}

TEST(JsonResults, BenchBandReportsTheBandAndItsSpeed)
{
  auto j = parseStdout(
      testing::runLbmshape({"bench", "--band", "--json", "--size", "48,40,40", "--steps", "2", "--runs", "1"}));
  EXPECT_EQ(j["device"], selectedDeviceName());
  const auto& band = j["band"];
  EXPECT_EQ(band["half_width"], 6.0) << "an isotropic denoise's at the default gamma (lbm/band_width.hpp)";
  const size_t stored = band["stored_cells"], stepped = band["stepped_cells"], streaming = band["streaming_cells"];
  EXPECT_EQ(stored, band["bricks"].get<size_t>() * 512);
  EXPECT_LE(streaming, stepped);
  EXPECT_LE(stepped, stored);
  EXPECT_GT(streaming, 0u);
  EXPECT_NEAR(band["fraction_of_grid"].get<double>(), double(stored) / (48 * 40 * 40), 1e-12);
  EXPECT_LT(band["device_bytes_per_stored_cell"].get<double>(), 40.0) << "the issue's goal for compact state";
  for (const char* backend : {"vulkan", "reference"}) {
    const auto& b = j[backend];
    ASSERT_TRUE(b.is_object()) << backend;
    const double ms = b["ms_per_step"];
    EXPECT_GT(ms, 0.0);
    EXPECT_NEAR(b["mlups"].get<double>(), double(stepped) / (ms * 1e3), 1e-6 * b["mlups"].get<double>());
    EXPECT_NEAR(b["stored_mlups"].get<double>(), double(stored) / (ms * 1e3), 1e-6 * b["stored_mlups"].get<double>());
  }
  EXPECT_NEAR(j["vulkan_over_reference"].get<double>(),
              j["vulkan"]["mlups"].get<double>() / j["reference"]["mlups"].get<double>(), 1e-9);
  expectDenoiseStages(j["denoise"], 48, "band", j["vulkan"]["stored_mlups"].get<double>());

  auto narrow = parseStdout(testing::runLbmshape(
      {"bench", "--band", "--half-width", "2", "--json", "--size", "48,40,40", "--steps", "1", "--runs", "1"}));
  EXPECT_EQ(narrow["band"]["half_width"], 2.0);
  EXPECT_LT(narrow["band"]["streaming_cells"].get<size_t>(), streaming);
}

TEST(JsonResults, BenchPaperTimesTheLatticesOfTableOne)
{
  auto j = parseStdout(testing::runLbmshape({"bench", "--paper", "--json", "--steps", "1", "--runs", "1"}));
  EXPECT_EQ(j["device"], selectedDeviceName());
  const auto& rows = j["table1"];
  ASSERT_EQ(rows.size(), 5u);
  const nlohmann::json sizes = {{70, 123, 66}, {107, 128, 97}, {58, 128, 106}, {128, 128, 128}, {80, 80, 80}};
  const double paperGpuMs[] = {3.1, 6.2, 3.7, 14.5, 4.5};  // Table 1 of the paper
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i]["size"], sizes[i]) << i;
    EXPECT_EQ(rows[i]["paper"]["gpu_ms_per_step"].get<double>(), paperGpuMs[i]) << i;
    EXPECT_GT(rows[i]["vulkan"]["ms_per_step"].get<double>(), 0.0) << i;
    EXPECT_GT(rows[i]["reference"]["ms_per_step"].get<double>(), 0.0) << i;
  }
  EXPECT_EQ(rows[3]["figure"], "Figure 8");
  EXPECT_EQ(rows[3]["application"], "morphing");
}

// The second run of a process finds the pipeline cache the first one saved in
// $XDG_CACHE_HOME/lbmshape, and a third that compiles nothing new leaves
// the file as it was.
TEST(JsonResults, PipelineCacheIsSavedAndLoadedAgain)
{
  testing::ScratchFolder cache;
  const std::string previous = std::getenv("XDG_CACHE_HOME") ? std::getenv("XDG_CACHE_HOME") : "";
  setenv("XDG_CACHE_HOME", cache.path().c_str(), 1);
  const std::vector<std::string> bench = {"bench", "--json", "--size", "16,16,16", "--steps", "1", "--runs", "1"};
  auto first = parseStdout(testing::runLbmshape(bench));
  auto second = parseStdout(testing::runLbmshape(bench));
  auto cacheFile = [&cache] {
    for (const auto& entry : std::filesystem::directory_iterator(cache / "lbmshape"))
      if (entry.path().extension() == ".bin") return entry.path();
    return std::filesystem::path();
  };
  const auto savedBySecond = std::filesystem::last_write_time(cacheFile());
  parseStdout(testing::runLbmshape(bench));
  const auto afterThird = std::filesystem::last_write_time(cacheFile());
  setenv("XDG_CACHE_HOME", previous.c_str(), 1);

  EXPECT_EQ(first["startup"]["pipeline_cache_loaded_bytes"].get<size_t>(), 0u) << "a fresh cache folder";
  EXPECT_GT(second["startup"]["pipeline_cache_loaded_bytes"].get<size_t>(), 0u);
  ASSERT_TRUE(std::filesystem::is_directory(cache / "lbmshape"));
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(cache / "lbmshape"))
    files += entry.path().extension() == ".bin";
  EXPECT_EQ(files, 1u);
  EXPECT_EQ(afterThird, savedBySecond) << "the third run compiled nothing new, yet wrote the cache again";
}

// The cache is optional: a named pipe, a folder or a link to /dev/zero in
// the cache file's place is passed over (they hung the start, threw, and
// ran out of memory), and a relative XDG_CACHE_HOME is ignored, as the XDG
// specification says, not made in the working folder.
TEST(JsonResults, ACacheFileThatIsNoFileIsPassedOver)
{
  testing::ScratchFolder cache;
  const std::string previous = std::getenv("XDG_CACHE_HOME") ? std::getenv("XDG_CACHE_HOME") : "";
  setenv("XDG_CACHE_HOME", cache.path().c_str(), 1);
  const std::vector<std::string> bench = {"bench", "--json", "--size", "16,16,16", "--steps", "1", "--runs", "1"};
  parseStdout(testing::runLbmshape(bench));
  std::filesystem::path file;
  for (const auto& entry : std::filesystem::directory_iterator(cache / "lbmshape"))
    if (entry.path().extension() == ".bin") file = entry.path();
  ASSERT_FALSE(file.empty());
  const std::function<void()> replacements[] = {
      [&] { ASSERT_EQ(::mkfifo(file.c_str(), 0666), 0); },
      [&] { std::filesystem::create_directory(file); },
      [&] { std::filesystem::create_symlink("/dev/zero", file); },
  };
  for (const auto& replace : replacements) {
    std::filesystem::remove(file);
    replace();
    const auto run = testing::runLbmshape(bench);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(parseStdout(run)["startup"]["pipeline_cache_loaded_bytes"].get<size_t>(), 0u);
  }
  testing::ScratchFolder work;
  const auto here = std::filesystem::current_path();
  const std::string home = std::getenv("HOME") ? std::getenv("HOME") : "";
  std::filesystem::current_path(work.path());
  setenv("XDG_CACHE_HOME", "relative/cache", 1);
  setenv("HOME", (work / "home").c_str(), 1);
  const auto relative = testing::runLbmshape(bench);
  std::filesystem::current_path(here);
  setenv("XDG_CACHE_HOME", previous.c_str(), 1);
  setenv("HOME", home.c_str(), 1);
  EXPECT_EQ(relative.exitCode, 0) << relative.err;
  EXPECT_FALSE(std::filesystem::exists(work / "relative"));
  EXPECT_TRUE(std::filesystem::is_directory(work / "home" / ".cache" / "lbmshape"));  // where HOME says instead
}

TEST(JsonResults, ReferenceDeviceRunsWithoutVulkan)
{
  auto j = parseStdout(testing::runLbmshape(
      {"--device", "reference", "bench", "--json", "--size", "12,12,12", "--steps", "3", "--runs", "1"}));
  EXPECT_TRUE(j["vulkan"].is_null());
  EXPECT_GT(j["reference"]["mlups"].get<double>(), 0.0);
}

}  // namespace
}  // namespace lbmshape
