// lbmshape run: a jobs file of denoise and morph jobs in one process. A job
// that fails (a missing file, an option of the wrong kind) is reported with
// its own exit code and does not stop the others, unless --fail-fast.
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

class JobsFile : public ::testing::Test {
protected:
  testing::ScratchFolder folder;
  void SetUp() override
  {
    writeMesh(testing::icosphere(3), folder / "sphere.obj");
    writeMesh(testing::torusMesh(1.0, 0.4, 48, 24), folder / "torus.obj");
  }
  fs::path write(const nlohmann::json& jobs)
  {
    const fs::path file = folder / "jobs.json";
    std::ofstream(file) << jobs.dump(2);
    return file;
  }
  nlohmann::json threeJobs()
  {
    return nlohmann::json::array({
        {{"command", "denoise"},
         {"input", "sphere.obj"},
         {"output", "sphere_smooth.glb"},
         {"res", 24},
         {"preserve-features", true}},
        {{"command", "denoise"}, {"input", "no_such_mesh.obj"}, {"output", "missing.glb"}, {"res", 24}},
        {{"command", "morph"},
         {"source", "sphere.obj"},
         {"target", "torus.obj"},
         {"output", "frames"},
         {"res", 24},
         {"frames", 3},
         {"gamma", 0.1}},
    });
  }
};

TEST_F(JobsFile, OneMissingFileFailsOnlyItsJob)
{
  testing::CliResult r = testing::runLbmshape({"run", write(threeJobs()).string(), "--json"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  ASSERT_EQ(report["results"].size(), 3u);
  EXPECT_TRUE(report["results"][0]["ok"].get<bool>());
  EXPECT_FALSE(report["results"][1]["ok"].get<bool>());
  EXPECT_EQ(report["results"][1]["exit_code"], 3);
  EXPECT_NE(report["results"][1]["error"].get<std::string>().find("no_such_mesh.obj"), std::string::npos);
  EXPECT_TRUE(report["results"][2]["ok"].get<bool>());
  EXPECT_TRUE(fs::exists(folder / "sphere_smooth.glb")) << "relative to the jobs file";
  EXPECT_TRUE(fs::exists(folder / "frames" / "frame_0002.glb"));
  EXPECT_EQ(report["results"][0]["report"]["smoothing"], "preserve-features");
  EXPECT_EQ(report["results"][2]["report"]["gamma"], 0.1);
  EXPECT_NE(r.err.find("no_such_mesh.obj"), std::string::npos) << "the failure is reported";
}

TEST_F(JobsFile, FailFastStopsAtTheFailure)
{
  testing::CliResult r = testing::runLbmshape({"run", write(threeJobs()).string(), "--fail-fast", "--json"});
  EXPECT_EQ(r.exitCode, 3);
  EXPECT_EQ(nlohmann::json::parse(r.out)["results"].size(), 2u);
  EXPECT_FALSE(fs::exists(folder / "frames"));
}

TEST_F(JobsFile, BadJobsAreUsageErrorsOfTheirOwn)
{
  auto jobs =
      nlohmann::json::array({{{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "a.glb"}, {"frobnicate", 1}},
                             {{"command", "explode"}},
                             {{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "b.glb"}, {"res", 20}}});
  testing::CliResult r = testing::runLbmshape({"run", write(jobs).string(), "--json"});
  EXPECT_EQ(r.exitCode, 2);
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report["failed"], 2);
  EXPECT_TRUE(report["results"][2]["ok"].get<bool>());
  testing::CliResult notJson = testing::runLbmshape({"run", (folder / "sphere.obj").string()});
  EXPECT_EQ(notJson.exitCode, 3);
  EXPECT_EQ(testing::nonEmptyLines(notJson.err).size(), 1u) << notJson.err;
}

// A job whose options are wrong is found before any job runs: said at once
// (the others still run), or with --fail-fast the run stops before the
// first job; --check checks every job and runs none. A mistake in the last
// job of a long batch used to surface only after all the others had run.
TEST_F(JobsFile, WrongOptionsAreFoundBeforeAnyJobRuns)
{
  nlohmann::json jobs = threeJobs();
  jobs[1] = {{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "fine.glb"}, {"res", 24}};
  jobs.push_back({{"command", "morph"},
                  {"source", "sphere.obj"},
                  {"target", "torus.obj"},
                  {"output", "late"},
                  {"frames", 1}});  // fewer than 2 frames
  jobs.push_back({{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "typo.glb"}, {"rez", 24}});
  const fs::path file = write(jobs);
  const auto nothingWritten = [&](const std::string& how) {
    for (const char* output : {"sphere_smooth.glb", "fine.glb", "frames", "late", "typo.glb"})
      EXPECT_FALSE(fs::exists(folder / output)) << how << ": " << output;
  };

  testing::CliResult check = testing::runLbmshape({"run", file.string(), "--check", "--json"});
  EXPECT_EQ(check.exitCode, 2) << check.err;
  nothingWritten("--check");
  const auto checked = nlohmann::json::parse(check.out);
  EXPECT_EQ(checked["run"], 0);
  EXPECT_EQ(checked["failed"], 2);
  ASSERT_EQ(checked["results"].size(), 5u);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(checked["results"][k]["ok"].get<bool>()) << checked["results"][k];
  EXPECT_NE(checked["results"][3]["error"].get<std::string>().find("job 4 (morph"), std::string::npos);
  EXPECT_NE(checked["results"][3]["error"].get<std::string>().find("--frames"), std::string::npos);
  EXPECT_NE(checked["results"][4]["error"].get<std::string>().find("unknown option \"rez\""), std::string::npos);
  EXPECT_NE(check.err.find("2 of 5 jobs have wrong options; first: job 4"), std::string::npos) << check.err;

  testing::CliResult failFast = testing::runLbmshape({"run", file.string(), "--fail-fast", "--json"});
  EXPECT_EQ(failFast.exitCode, 2) << failFast.err;
  nothingWritten("--fail-fast");
  const auto stopped = nlohmann::json::parse(failFast.out);
  ASSERT_EQ(stopped["results"].size(), 1u);
  EXPECT_EQ(stopped["results"][0]["job"], 4);
  EXPECT_NE(failFast.err.find("found before any job ran"), std::string::npos) << failFast.err;

  testing::CliResult all = testing::runLbmshape({"run", file.string(), "--json"});
  EXPECT_EQ(all.exitCode, 2) << all.err;
  const auto lines = testing::nonEmptyLines(all.err);
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(all.err.find("2 of 5 jobs have wrong options and will fail when their turn comes"), std::string::npos)
      << all.err;
  EXPECT_TRUE(fs::exists(folder / "fine.glb")) << "the right jobs still run";

  jobs.erase(4);
  jobs.erase(3);
  fs::remove_all(folder / "frames");
  testing::CliResult fine = testing::runLbmshape({"run", write(jobs).string(), "--check"});
  EXPECT_EQ(fine.exitCode, 0) << fine.err;
  EXPECT_FALSE(fs::exists(folder / "frames")) << "--check runs nothing";
}

// An output of no mesh format and a preview that is not .png are usage
// errors of the job's options: --check finds them, and --fail-fast stops
// before any job (both let them through, and the first job ran).
TEST_F(JobsFile, OutputAndPreviewNamesAreCheckedBeforeAnyJobRuns)
{
  nlohmann::json jobs = nlohmann::json::array(
      {{{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "a.glb"}, {"res", 20}},
       {{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "i.xyz"}, {"res", 20}},
       {{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "b.glb"}, {"preview", "p.jpg"}},
       {{"command", "morph"},
        {"source", "sphere.obj"},
        {"target", "torus.obj"},
        {"output", "m"},
        {"preview", "m.jpg"}}});
  const fs::path file = write(jobs);
  testing::CliResult check = testing::runLbmshape({"run", file.string(), "--check", "--json"});
  EXPECT_EQ(check.exitCode, 2) << check.err;
  const auto checked = nlohmann::json::parse(check.out);
  EXPECT_EQ(checked["failed"], 3);
  EXPECT_NE(checked["results"][1]["error"].get<std::string>().find("unknown mesh format '.xyz'"), std::string::npos)
      << checked["results"][1];
  EXPECT_NE(checked["results"][2]["error"].get<std::string>().find("p.jpg must be a .png file"), std::string::npos)
      << checked["results"][2];
  EXPECT_NE(checked["results"][3]["error"].get<std::string>().find("m.jpg must be a .png file"), std::string::npos)
      << checked["results"][3];
  testing::CliResult failFast = testing::runLbmshape({"run", file.string(), "--fail-fast", "--json"});
  EXPECT_EQ(failFast.exitCode, 2) << failFast.err;
  EXPECT_FALSE(fs::exists(folder / "a.glb")) << "no job ran";
  EXPECT_EQ(nlohmann::json::parse(failFast.out)["run"], 0);
}

// A job that reads what another job writes after it, or in another part of
// --shard (the parts run side by side), is warned about, naming both jobs:
// it would read an older file, or none. A frame in a morph's folder counts
// as what the morph writes.
TEST_F(JobsFile, AJobThatReadsAnotherJobsLaterOutputIsWarnedAbout)
{
  const nlohmann::json jobs = nlohmann::json::array({
      {{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "a.glb"}, {"res", 16}},
      {{"command", "denoise"}, {"input", "torus.obj"}, {"output", "b.glb"}, {"res", 16}},
      {{"command", "morph"}, {"source", "a.glb"}, {"target", "./b.glb"}, {"output", "m"}, {"res", 16}},
      {{"command", "morph"}, {"source", "m/frame_0001.glb"}, {"target", "c.glb"}, {"output", "m2"}, {"res", 16}},
      {{"command", "denoise"}, {"input", "torus.obj"}, {"output", "c.glb"}, {"res", 16}},
  });
  const fs::path file = write(jobs);
  const testing::CliResult whole = testing::runLbmshape({"run", file.string(), "--check"});
  EXPECT_EQ(whole.exitCode, 0) << whole.err;
  auto warnings = [](const std::string& err) {
    std::vector<std::string> found;
    for (const std::string& line : testing::nonEmptyLines(err))
      if (line.find("warning: job") != std::string::npos) found.push_back(line);
    return found;
  };
  ASSERT_EQ(warnings(whole.err).size(), 1u) << "only job 4 reads a later job's output\n" << whole.err;
  EXPECT_NE(warnings(whole.err)[0].find("job 4 reads c.glb, which job 5 writes after it"), std::string::npos)
      << whole.err;

  const testing::CliResult part = testing::runLbmshape({"run", file.string(), "--check", "--shard", "1/2"});
  EXPECT_EQ(part.exitCode, 0) << part.err;
  ASSERT_EQ(warnings(part.err).size(), 1u) << "job 3 of part 1 reads job 2's output, of part 2\n" << part.err;
  EXPECT_NE(warnings(part.err)[0].find("job 3 reads ./b.glb, which job 2 writes in another part of --shard"),
            std::string::npos)
      << part.err;
}

// A key twice in one job, or two jobs writing one output (by different
// spellings of the path too), would make one silently win: both are refused
// before any job runs, naming the job and the key or the two jobs.
TEST_F(JobsFile, DuplicateKeysAndOutputsAreRefusedBeforeAnyJob)
{
  const fs::path file = folder / "jobs.json";
  std::ofstream(file) << R"([{"command": "denoise", "input": "sphere.obj", "output": "a.glb"},
                             {"command": "denoise", "input": "sphere.obj", "output": "b.glb", "res": 16, "res": 32}])";
  testing::CliResult twice = testing::runLbmshape({"run", file.string()});
  EXPECT_EQ(twice.exitCode, 2) << twice.err;
  EXPECT_NE(twice.err.find("job 2 gives \"res\" twice"), std::string::npos) << twice.err;
  EXPECT_FALSE(fs::exists(folder / "a.glb")) << "no job ran";

  auto jobs = nlohmann::json::array(
      {{{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "same.glb"}, {"res", 16}},
       {{"command", "denoise"}, {"input", "torus.obj"}, {"output", "other.glb"}, {"res", 16}},
       {{"command", "denoise"}, {"input", "torus.obj"}, {"output", "./x/../same.glb"}, {"res", 16}}});
  fs::create_directory(folder / "x");
  testing::CliResult same = testing::runLbmshape({"run", write(jobs).string()});
  EXPECT_EQ(same.exitCode, 2) << same.err;
  EXPECT_NE(same.err.find("jobs 1 and 3 both write ./x/../same.glb"), std::string::npos) << same.err;
  EXPECT_FALSE(fs::exists(folder / "same.glb")) << "no job ran";
}

// A morph's folder with and without its trailing slash is one folder; a
// preview picture is an output too; and a job writing into a morph's
// folder of frames could replace a frame. Each is refused before any job.
TEST_F(JobsFile, OutputsThatMeetAnotherWayAreRefusedBeforeAnyJob)
{
  const nlohmann::json morph = {
      {"command", "morph"}, {"source", "sphere.obj"}, {"target", "torus.obj"}, {"output", "frames"}, {"res", 16},
      {"frames", 2}};
  const auto refused = [&](nlohmann::json second, const std::string& expected) {
    testing::CliResult r = testing::runLbmshape({"run", write(nlohmann::json::array({morph, second})).string()});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(testing::nonEmptyLines(r.err).size(), 1u) << r.err;
    EXPECT_FALSE(fs::exists(folder / "frames")) << "no job ran";
  };
  nlohmann::json slash = morph;
  slash["output"] = "frames/";
  slash["force"] = true;
  refused(slash, "jobs 1 and 2 both write frames/");
  refused({{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "frames/frame_0001.glb"}, {"res", 16}},
          "job 2 writes frames/frame_0001.glb into job 1's folder of frames frames");
  nlohmann::json previewing = morph;
  previewing["preview"] = "sheet.png";
  testing::CliResult r = testing::runLbmshape({"run", write(nlohmann::json::array({previewing,
                                                                                   {{"command", "denoise"},
                                                                                    {"input", "sphere.obj"},
                                                                                    {"output", "a.glb"},
                                                                                    {"preview", "./sheet.png"},
                                                                                    {"res", 16}}}))
                                                          .string()});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("jobs 1 and 2 both write ./sheet.png"), std::string::npos) << r.err;
}

// The jobs of one run share one device, opened once (-v logs "device:" when
// it opens). A morph creates its output folder, parents and all; a
// denoise's folder must exist.
TEST_F(JobsFile, JobsShareOneDeviceAndMorphCreatesItsFolder)
{
  auto jobs = nlohmann::json::array(
      {{{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "smooth.obj"}, {"res", 16}},
       {{"command", "morph"},
        {"source", "sphere.obj"},
        {"target", "torus.obj"},
        {"output", "new/nested/frames"},
        {"res", 16},
        {"frames", 2}},
       {{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "no_such_folder/smooth.obj"}, {"res", 16}}});
  testing::CliResult r = testing::runLbmshape({"-v", "run", write(jobs).string(), "--json"});
  EXPECT_EQ(r.exitCode, 4) << r.err;
  const auto lines = testing::nonEmptyLines(r.err);
  EXPECT_EQ(std::count_if(lines.begin(), lines.end(),
                          [](const std::string& l) { return l.rfind("lbmshape: device: ", 0) == 0; }),
            1)
      << r.err;
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_TRUE(report["results"][0]["ok"].get<bool>());
  EXPECT_TRUE(report["results"][1]["ok"].get<bool>());
  EXPECT_TRUE(fs::exists(folder / "new" / "nested" / "frames" / "frame_0001.glb"));
  EXPECT_EQ(report["results"][2]["exit_code"], 4);
  EXPECT_NE(report["results"][2]["error"].get<std::string>().find("does not exist"), std::string::npos)
      << report["results"][2]["error"];
}

// Options of the wrong JSON type, unknown keys and missing paths: each is a
// usage error of its own job, naming the key, and the other jobs still run.
struct JobCase {
  const char* name;
  nlohmann::json options;  // added to a denoise job of sphere.obj at --res 16
  const char* errorNames;  // in the job's error; empty: the job succeeds
};

const JobCase jobCases[] = {
    {"string_for_a_whole_number", {{"res", "big"}}, "\"res\""},
    {"fraction_for_a_whole_number", {{"res", 96.5}}, "\"res\""},
    {"whole_float_is_a_whole_number", {{"res", 16.0}}, ""},
    {"true_for_a_number", {{"res", true}}, "\"res\""},
    {"array_for_a_number", {{"res", {16}}}, "\"res\""},
    {"string_for_a_number", {{"gamma", "0.1"}}, "\"gamma\""},
    {"negative_number_as_value", {{"gamma", -0.1}}, "--gamma"},  // a value, not an option: the command's own check
    {"string_for_a_flag", {{"anisotropic", "yes"}}, "\"anisotropic\""},
    {"number_for_a_flag", {{"anisotropic", 1}}, "\"anisotropic\""},
    {"false_flag", {{"anisotropic", false}}, ""},
    {"null_is_the_default", {{"gamma", nullptr}}, ""},
    {"unknown_key", {{"frobnicate", 1}}, "\"frobnicate\""},
    {"help_is_no_job_option", {{"help", true}}, "\"help\""},
    {"missing_output", {{"output", nullptr}}, "\"output\""},
    // "--preview=" would take the next argument as its value.
    {"empty_string", {{"preview", ""}}, "option \"preview\" is empty"},
    // The system would end the name at the NUL and write another file.
    {"nul_in_a_value", {{"preview", std::string("a\0.png", 6)}}, "option \"preview\" holds a NUL character"},
    {"nul_in_a_path", {{"output", std::string("out\0.glb", 8)}}, "\"output\" holds a NUL character"},
    {"negative_seed", {{"seed", -1}}, "option \"seed\" must be a whole number from 0"},
    {"seed_beyond_32_bits", {{"seed", 4294967296LL}}, "option \"seed\" must be a whole number from 0"},
    {"res_of_a_trillion", {{"res", 1e12}}, "option \"res\" is 1000000000000.0, far beyond any value it takes"},
};

TEST_F(JobsFile, OptionsOfTheWrongKindFailOnlyTheirJob)
{
  // First a job with a missing file (exit code 3), then the table: the run's
  // exit code is that of the first job that failed.
  nlohmann::json jobs = nlohmann::json::array(
      {{{"command", "denoise"}, {"input", "no_such_mesh.obj"}, {"output", "missing.glb"}, {"res", 16}}});
  for (const JobCase& c : jobCases) {
    nlohmann::json job = {
        {"command", "denoise"}, {"input", "sphere.obj"}, {"output", std::string(c.name) + ".obj"}, {"res", 16}};
    job.update(c.options);
    if (job["output"].is_null()) job.erase("output");
    jobs.push_back(job);
  }
  testing::CliResult r = testing::runLbmshape({"run", write(jobs).string(), "--json"});
  EXPECT_EQ(r.exitCode, 3) << "the first failure's exit code\n" << r.err;
  const auto report = nlohmann::json::parse(r.out);
  ASSERT_EQ(report["results"].size(), jobs.size());
  int failures = 1;
  for (size_t i = 0; i < std::size(jobCases); ++i) {
    const JobCase& c = jobCases[i];
    const auto& result = report["results"][i + 1];
    const std::string job = "job " + std::to_string(i + 2);
    if (*c.errorNames == '\0') {
      EXPECT_TRUE(result["ok"].get<bool>()) << c.name << ": " << result.dump();
      continue;
    }
    ++failures;
    ASSERT_FALSE(result["ok"].get<bool>()) << c.name;
    EXPECT_EQ(result["exit_code"], 2) << c.name << ": a usage error";
    EXPECT_NE(result["error"].get<std::string>().find(c.errorNames), std::string::npos)
        << c.name << ": " << result["error"];
    const std::string line = "failed: " + result["error"].get<std::string>();
    const auto lines = testing::nonEmptyLines(r.err);
    EXPECT_TRUE(std::any_of(lines.begin(), lines.end(),
                            [&](const std::string& l) {
                              return l.rfind("lbmshape: warning: " + job + " ", 0) == 0 && l.size() >= line.size() &&
                                     l.compare(l.size() - line.size(), line.size(), line) == 0;
                            }))
        << c.name << ": the log names the job\n"
        << r.err;
    EXPECT_FALSE(fs::exists(folder / (std::string(c.name) + ".obj"))) << c.name;
  }
  EXPECT_EQ(report["failed"], failures);
  // 16.0 was read as 16 cells along the longest side.
  EXPECT_EQ(report["results"][3]["report"]["grid"]["size"][0], 16);
}

// Five small denoise jobs, for splitting into parts.
nlohmann::json fiveDenoiseJobs()
{
  nlohmann::json jobs = nlohmann::json::array();
  for (int k = 1; k <= 5; ++k)
    jobs.push_back(
        {{"command", "denoise"}, {"input", "sphere.obj"}, {"output", "s" + std::to_string(k) + ".obj"}, {"res", 16}});
  return jobs;
}

TEST_F(JobsFile, ShardsSplitTheJobsSoEachRunsExactlyOnce)
{
  const fs::path file = write(fiveDenoiseJobs());
  std::vector<int> ran;
  for (const char* shard : {"1/2", "2/2"}) {
    testing::CliResult r = testing::runLbmshape({"run", file.string(), "--shard", shard, "--json", "-q"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto report = nlohmann::json::parse(r.out);
    EXPECT_EQ(report["jobs"], 5);
    EXPECT_EQ(report["shard"], shard);
    for (const auto& result : report["results"]) ran.push_back(result["job"].get<int>());
  }
  EXPECT_EQ(ran, (std::vector<int>{1, 3, 5, 2, 4})) << "part K of N: jobs K, K + N, ...";
  for (int k = 1; k <= 5; ++k) EXPECT_TRUE(fs::exists(folder / ("s" + std::to_string(k) + ".obj"))) << k;
}

TEST_F(JobsFile, AShardThatIsNoPartIsAUsageErrorBeforeAnyJob)
{
  const fs::path file = write(fiveDenoiseJobs());
  for (const char* shard : {"0/2", "3/2", "2", "1/0", "a/b", "1/2x", "-1/2"}) {
    testing::CliResult r = testing::runLbmshape({"run", file.string(), "--shard", shard});
    EXPECT_EQ(r.exitCode, 2) << shard << ": " << r.err;
    EXPECT_NE(r.err.find("--shard must be K/N"), std::string::npos) << r.err;
    EXPECT_EQ(testing::messageLines(r.err).size(), 1u) << r.err;
  }
  EXPECT_FALSE(fs::exists(folder / "s1.obj"));
}

// The batch recipe of docs/scaling.md: GNU parallel runs the parts at once.
TEST_F(JobsFile, GnuParallelRunsThePartsSideBySide)
{
  if (std::system("command -v parallel > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "GNU parallel is not installed (Debian: apt-get install parallel; scripts/install-deps.sh "
                    "--with-test-tools installs it)";
  const fs::path file = write(fiveDenoiseJobs());
  const std::string command = "parallel --halt now,fail=1 '" + testing::lbmshapeBinary() + "' -q run '" +
                              file.string() + "' --shard {}/3 ::: 1 2 3";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  for (int k = 1; k <= 5; ++k) EXPECT_TRUE(fs::exists(folder / ("s" + std::to_string(k) + ".obj"))) << k;
}

}  // namespace
}  // namespace lbmshape
