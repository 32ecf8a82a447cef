// lbmshape morph and lbmshape run as a user runs them.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <fstream>
#include <map>

#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/cli_runner.hpp"
#include "support/glb_json.hpp"
#include "support/gltf_validator.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

class MorphCli : public ::testing::Test {
protected:
  testing::ScratchFolder folder;
  std::string sphere = (folder / "sphere.obj").string(), torus = (folder / "torus.obj").string();
  void SetUp() override
  {
    writeMesh(testing::icosphere(3), sphere);
    writeMesh(testing::torusMesh(1.0, 0.4, 48, 24), torus);
  }
};

TEST_F(MorphCli, FramesAndAnimationAreValidGltf)
{
  const fs::path out = folder / "frames";
  testing::CliResult r = testing::runLbmshape(
      {"morph", sphere, torus, out.string(), "--res", "32", "--frames", "5", "--fps", "10", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (int k = 0; k < 5; ++k) {
    const fs::path frame = out / ("frame_000" + std::to_string(k) + ".glb");
    const auto v = testing::validateGltf(frame);
    EXPECT_TRUE(v.passed()) << frame << ": " << v;
  }
  const auto v = testing::validateGltf(out / "morph.glb");
  EXPECT_TRUE(v.passed()) << v;
  const nlohmann::json gltf = testing::glbJson(out / "morph.glb");
  EXPECT_EQ(gltf["nodes"].size(), 5u);
  ASSERT_EQ(gltf["animations"].size(), 1u);
  double end = 0.0;
  for (const auto& sampler : gltf["animations"][0]["samplers"]) {
    const auto& input = gltf["accessors"][sampler["input"].get<size_t>()];
    end = std::max(end, input["max"][0].get<double>());
  }
  EXPECT_NEAR(end, 5 / 10.0, 1e-6) << "the animation spans frames / fps";
  auto report = nlohmann::json::parse(r.out);
  for (const char* key : {"steps", "frames", "converged_at_step", "ms", "mlups", "final"})
    EXPECT_TRUE(report.contains(key)) << key;
  for (const char* stage : {"sdf", "lbm", "extract", "write", "commit", "last_frames", "final_figures"})
    EXPECT_TRUE(report["ms"].contains(stage)) << stage;
  EXPECT_GT(report["device_ms"].value("lbm", 0.0), 0.0) << report["device_ms"];
  for (const auto& [stage, ms] : report["device_ms"].items())
    EXPECT_LE(ms.get<double>(), report["ms"][stage].get<double>()) << stage;
  EXPECT_TRUE(report["final"].contains("mean_distance_to_target"));
}

// Frames are extracted and written on a thread of their own while the
// lattice goes on; two runs interleave differently, and must still write the
// same bytes.
// A full disk or a file-size limit part way through: the frames before the
// failure stay whole, and the error says which (it named only the file
// that failed, and a user had to list the folder).
TEST_F(MorphCli, AWriteThatFailsPartWaySaysWhichFramesAreComplete)
{
  // Torus to sphere: the frames grow, so a limit between the first's size
  // and the last's fails part way.
  const std::vector<std::string> job = {
      "morph", torus, sphere, (folder / "frames").string(), "--res", "32", "--frames", "6", "-q", "--no-animation"};
  ASSERT_EQ(testing::runLbmshape(job).exitCode, 0);
  const uintmax_t first = fs::file_size(folder / "frames" / "frame_0000.glb"),
                  last = fs::file_size(folder / "frames" / "frame_0005.glb");
  ASSERT_GT(last, first + 4096);
  fs::remove_all(folder / "frames");

  const testing::CliResult limited = testing::runLbmshapeWithFileSizeLimit((first + last) / 2, job);
  EXPECT_EQ(limited.exitCode, 4);
  const std::string& message = limited.err;
  std::vector<std::string> frames;
  for (const auto& entry : fs::directory_iterator(folder / "frames"))
    if (entry.path().filename().string().starts_with("frame_")) frames.push_back(entry.path().filename().string());
  std::sort(frames.begin(), frames.end());
  ASSERT_GE(frames.size(), 1u) << message;
  ASSERT_LT(frames.size(), 6u) << message;
  const std::string said =
      frames.size() == 1 ? frames[0] + " is complete" : frames.front() + " to " + frames.back() + " are complete";
  EXPECT_NE(message.find(said + " in " + (folder / "frames").string()), std::string::npos) << message;
}

TEST_F(MorphCli, FramesDoNotDependOnTheWritersTiming)
{
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const char* run : {"a", "b"})
    ASSERT_EQ(testing::runLbmshape({"morph", sphere, torus, (folder / run).string(), "--res", "40", "--frames", "12",
                                    "--format", "obj", "--no-animation"})
                  .exitCode,
              0);
  for (int k = 0; k < 12; ++k) {
    const std::string name =
        k < 10 ? "frame_000" + std::to_string(k) + ".obj" : "frame_00" + std::to_string(k) + ".obj";
    const std::string a = bytes(folder / "a" / name);
    EXPECT_FALSE(a.empty()) << name;
    EXPECT_EQ(a, bytes(folder / "b" / name)) << name;
  }
}

// The lattice runs on the narrow band unless --dense asks for every cell of
// the grid; --band, the default, is still accepted, but not with --dense.
TEST_F(MorphCli, RunsOnTheBandUnlessDense)
{
  auto kind = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"morph",          sphere,  torus,      (folder / extra.front()).string(),
                                     "--res",          "24",    "--frames", "3",
                                     "--no-animation", "--json"};
    args.insert(args.end(), extra.begin() + 1, extra.end());
    testing::CliResult r = testing::runLbmshape(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.exitCode == 0 ? nlohmann::json::parse(r.out)["lattice"]["kind"].get<std::string>() : "";
  };
  EXPECT_EQ(kind({"default"}), "band");
  EXPECT_EQ(kind({"named", "--band"}), "band");
  EXPECT_EQ(kind({"dense", "--dense"}), "grid");
  testing::CliResult both =
      testing::runLbmshape({"morph", sphere, torus, (folder / "both").string(), "--res", "24", "--band", "--dense"});
  EXPECT_EQ(both.exitCode, 2) << both.err;
  EXPECT_FALSE(fs::exists(folder / "both"));
}

// --sdf device: the two meshes' distances computed on the device, one
// after the other (the morph computes them side by side on the CPU), give
// the frames of the CPU's distances (within what the CPU's propagated
// distances add: tests/cli/denoise_cli_test.cpp,
// TheDistancesOnTheDeviceGiveTheSameMesh).
TEST_F(MorphCli, TheDistancesOnTheDeviceGiveTheSameFrames)
{
  double voxel = 0.0;
  for (const std::string where : {"cpu", "device"}) {
    testing::CliResult r = testing::runLbmshape({"morph", sphere, torus, (folder / where).string(), "--res", "32",
                                                 "--frames", "3", "--no-animation", "--sdf", where, "--json"});
    ASSERT_EQ(r.exitCode, 0) << where << ": " << r.err;
    voxel = nlohmann::json::parse(r.out)["grid"]["voxel"].get<double>();
  }
  for (const char* frame : {"frame_0001.glb", "frame_0002.glb"}) {
    testing::CliResult compared = testing::runLbmshape(
        {"compare", (folder / "cpu" / frame).string(), (folder / "device" / frame).string(), "--json"});
    ASSERT_EQ(compared.exitCode, 0) << compared.err;
    const auto c = nlohmann::json::parse(compared.out);
    EXPECT_LT(c["hausdorff"].get<double>(), 0.05 * voxel) << frame << ": " << c;
    EXPECT_LT(c["mean"].get<double>(), 1e-3 * voxel) << frame << ": " << c;
  }
}

// --extract device: each frame's marching cubes on the device, only its
// surface's pieces read back (and the field's values where the frame's
// figures sample it), give the CPU's frames from the whole field: the same
// vertices and triangles in the same order, the normals to float rounding,
// the same figures.
TEST_F(MorphCli, TheFramesExtractedOnTheDeviceAreTheCpus)
{
  std::map<std::string, nlohmann::json> reports;
  for (const std::string where : {"cpu", "device"}) {
    testing::CliResult r = testing::runLbmshape({"morph", sphere, torus, (folder / where).string(), "--res", "32",
                                                 "--frames", "4", "--no-animation", "--extract", where, "--json"});
    ASSERT_EQ(r.exitCode, 0) << where << ": " << r.err;
    reports[where] = nlohmann::json::parse(r.out);
    EXPECT_EQ(reports[where]["extract_on"], where);
  }
  EXPECT_EQ(reports["device"]["per_frame"], reports["cpu"]["per_frame"]);
  EXPECT_EQ(reports["device"]["final"], reports["cpu"]["final"]);
  EXPECT_EQ(reports["device"]["max_band_error_voxels"], reports["cpu"]["max_band_error_voxels"]);
  for (const char* frame : {"frame_0000.glb", "frame_0002.glb", "frame_0003.glb"}) {
    const TriangleMesh cpu = readMesh(folder / "cpu" / frame), device = readMesh(folder / "device" / frame);
    EXPECT_EQ(device.positions, cpu.positions) << frame;
    EXPECT_EQ(device.triangles, cpu.triangles) << frame;
    ASSERT_EQ(device.normals.size(), cpu.normals.size()) << frame;
    for (size_t v = 0; v < cpu.normals.size(); ++v)
      ASSERT_LT(glm::length(device.normals[v] - cpu.normals[v]), 1e-5f) << frame << ", vertex " << v;
  }
}

// The same read back through staging buffers, as on a discrete GPU
// (LBMSHAPE_STAGED_READBACK=1; lavapipe's device memory is the host's,
// which the runs above read in place): the same frames and figures.
TEST_F(MorphCli, TheFramesReadBackThroughStagingAreTheSame)
{
  std::map<std::string, nlohmann::json> reports;
  for (const std::string where : {"cpu", "device"}) {
    for (const bool staged : {false, true}) {
      const std::string run = where + (staged ? "-staged" : "");
      if (staged) setenv("LBMSHAPE_STAGED_READBACK", "1", 1);
      testing::CliResult r = testing::runLbmshape({"morph", sphere, torus, (folder / run).string(), "--res", "32",
                                                   "--frames", "4", "--no-animation", "--extract", where, "--json"});
      unsetenv("LBMSHAPE_STAGED_READBACK");
      ASSERT_EQ(r.exitCode, 0) << run << ": " << r.err;
      reports[run] = nlohmann::json::parse(r.out);
    }
    EXPECT_EQ(reports[where + "-staged"]["per_frame"], reports[where]["per_frame"]) << where;
    EXPECT_EQ(reports[where + "-staged"]["final"], reports[where]["final"]) << where;
    const TriangleMesh direct = readMesh(folder / where / "frame_0002.glb"),
                       staged = readMesh(folder / (where + "-staged") / "frame_0002.glb");
    EXPECT_EQ(staged.positions, direct.positions) << where;
    EXPECT_EQ(staged.triangles, direct.triangles) << where;
  }
}

// --extract takes auto, cpu or device; device needs a Vulkan device; the
// grid's frames, which have no device path, warn.
TEST_F(MorphCli, ExtractIsCpuDeviceOrAuto)
{
  testing::CliResult r = testing::runLbmshape({"morph", sphere, torus, (folder / "a").string(), "--extract", "gpu"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--extract"), std::string::npos) << r.err;
  r = testing::runLbmshape(
      {"morph", sphere, torus, (folder / "b").string(), "--res", "24", "--extract", "device", "--device", "reference"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--extract device needs a Vulkan device"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(folder / "b"));
  r = testing::runLbmshape({"morph", sphere, torus, (folder / "c").string(), "--res", "24", "--frames", "3",
                            "--extract", "DEVICE", "--dense", "--no-animation", "--json"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("warning: --extract device lists the narrow band's surfaces"), std::string::npos) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["extract_on"], "cpu");
}

TEST_F(MorphCli, OtherFrameFormats)
{
  for (const char* format : {"obj", "ply"}) {
    const fs::path out = folder / format;
    ASSERT_EQ(testing::runLbmshape({"morph", sphere, torus, out.string(), "--res", "24", "--frames", "3", "--format",
                                    format, "--no-animation"})
                  .exitCode,
              0);
    EXPECT_NO_THROW(readMesh(out / (std::string("frame_0002.") + format)));
    EXPECT_FALSE(fs::exists(out / "morph.glb"));
  }
}

struct BadMorph {
  const char* name;
  int exitCode;
  std::vector<std::string> extra;  // after "morph"; SPHERE, TORUS, OUT, FILE, MISSING, SHEET, SLAB are replaced
};

void PrintTo(const BadMorph& c, std::ostream* os) { *os << c.name; }

class MorphBadInput : public MorphCli, public ::testing::WithParamInterface<BadMorph> {};

TEST_P(MorphBadInput, ExitCodeAndOneLine)
{
  std::ofstream(folder / "afile") << "x";
  std::vector<std::string> args = {"morph"};
  for (std::string a : GetParam().extra) {
    if (a == "SPHERE") a = sphere;
    if (a == "TORUS") a = torus;
    if (a == "OUT") a = (folder / "out").string();
    if (a == "FILE") a = (folder / "afile" / "out").string();
    if (a == "MISSING") a = (folder / "missing.obj").string();
    if (a == "SHEET") {  // half a cylinder, triangles facing its axis: it encloses nothing
      a = (folder / "sheet.obj").string();
      writeMesh(testing::sheet(16,
                               [](double u, double v) {
                                 const double angle = std::numbers::pi * (1.0 - u);
                                 return glm::dvec3(std::cos(angle), std::sin(angle), 2.0 * v - 1.0);
                               }),
                a);
    }
    if (a == "TINY") {  // a thousandth of the sphere: less than a voxel of the grid the two share
      a = (folder / "tiny.obj").string();
      writeMesh(testing::icosphere(2, 0.001), a);
    }
    if (a == "SLAB") {  // 0.4 thick: at --res 16 its cells inside lie under a voxel deep, at 40 two
      a = (folder / "slab.obj").string();
      writeMesh(testing::box({-0.8, -0.8, -0.2}, {0.8, 0.8, 0.2}), a);
    }
    args.push_back(a);
  }
  testing::CliResult r = testing::runLbmshape(args);
  EXPECT_EQ(r.exitCode, GetParam().exitCode) << r.err;
  if (GetParam().exitCode != 0) {
    EXPECT_EQ(testing::messageLines(r.err).size(), 1u) << r.err;
    EXPECT_FALSE(fs::exists(folder / "out")) << "nothing written, not even the folder";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, MorphBadInput,
    ::testing::Values(
        BadMorph{"missing_target", 3, {"SPHERE", "MISSING", "OUT", "--res", "16"}},
        BadMorph{"missing_source", 3, {"MISSING", "TORUS", "OUT", "--res", "16"}},
        BadMorph{"target_encloses_nothing", 3, {"SPHERE", "SHEET", "OUT", "--res", "16"}},
        BadMorph{"source_encloses_nothing", 3, {"SHEET", "SPHERE", "OUT", "--res", "16"}},
        BadMorph{"target_smaller_than_a_voxel", 3, {"SPHERE", "TINY", "OUT", "--res", "16", "--align", "none"}},
        BadMorph{"source_smaller_than_a_voxel", 3, {"TINY", "SPHERE", "OUT", "--res", "16", "--align", "center"}},
        BadMorph{"a_tiny_target_fitted_is_fine", 0, {"SPHERE", "TINY", "OUT", "--res", "16", "--frames", "2", "-q"}},
        // Inside, but shallower than the tolerance: a last frame within it could hold no inside.
        BadMorph{"target_shallower_than_the_tolerance",
                 3,
                 {"SPHERE", "SLAB", "OUT", "--res", "16", "--align", "none", "--tolerance", "1"}},
        BadMorph{"target_deeper_than_the_tolerance",
                 0,
                 {"SPHERE", "SLAB", "OUT", "--res", "40", "--align", "none", "--frames", "2", "-q"}},
        BadMorph{"same_file_twice_is_fine", 0, {"SPHERE", "SPHERE", "OUT", "--res", "16", "--frames", "2", "-q"}},
        BadMorph{"unwritable_folder", 4, {"SPHERE", "TORUS", "FILE", "--res", "16"}},
        BadMorph{"one_frame", 2, {"SPHERE", "TORUS", "OUT", "--frames", "1"}},
        BadMorph{"zero_cs", 2, {"SPHERE", "TORUS", "OUT", "--cs", "0"}},
        BadMorph{"negative_cs", 2, {"SPHERE", "TORUS", "OUT", "--cs", "-0.1"}},
        BadMorph{"cs_too_slow_to_arrive", 2, {"SPHERE", "TORUS", "OUT", "--cs", "1e-9"}},
        BadMorph{"bad_format", 2, {"SPHERE", "TORUS", "OUT", "--format", "xyz"}},
        BadMorph{"bad_align", 2, {"SPHERE", "TORUS", "OUT", "--align", "sideways"}},
        BadMorph{"both_step_options", 2, {"SPHERE", "TORUS", "OUT", "--steps", "9", "--steps-per-frame", "2"}},
        // 0 is a value to refuse, not "the default": a morph of no steps only repeats the source.
        BadMorph{"zero_steps", 2, {"SPHERE", "TORUS", "OUT", "--steps", "0"}},
        BadMorph{"zero_steps_per_frame", 2, {"SPHERE", "TORUS", "OUT", "--steps-per-frame", "0"}},
        BadMorph{"zero_voxel", 2, {"SPHERE", "TORUS", "OUT", "--voxel", "0"}},
        // The bounds of core/parameter_bounds.hpp, refused before any work.
        BadMorph{"cs_above_one", 2, {"SPHERE", "TORUS", "OUT", "--cs", "1.5"}},
        BadMorph{"gamma_above_one", 2, {"SPHERE", "TORUS", "OUT", "--gamma", "1e9"}},
        BadMorph{"too_many_frames", 2, {"SPHERE", "TORUS", "OUT", "--frames", "100001"}},
        BadMorph{"too_many_steps", 2, {"SPHERE", "TORUS", "OUT", "--frames", "1000", "--steps-per-frame", "2000"}}),
    [](const auto& info) { return std::string(info.param.name); });

using testing::spawnLbmshape;

using testing::waitForFile;

using testing::waitForExit;

// Only complete frame files, each readable; returns how many.
int expectOnlyCompleteFrames(const fs::path& folder)
{
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.rfind("frame_", 0), 0u) << "only frame files, no temporary ones: " << name;
    EXPECT_NO_THROW(readMesh(entry.path())) << name;
    ++frames;
  }
  return frames;
}

TEST_F(MorphCli, CtrlCLeavesOnlyCompleteFrames)
{
  const fs::path out = folder / "frames";
  const pid_t pid = spawnLbmshape({"-q", "morph", sphere, torus, out.string(), "--res", "64", "--frames", "400",
                                   "--format", "obj", "--no-animation"});
  ASSERT_GT(pid, 0);
  waitForFile(out / "frame_0003.obj", std::chrono::seconds(60));  // a few frames, then Ctrl-C
  kill(pid, SIGINT);
  const int status = waitForExit(pid, std::chrono::seconds(60));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const int frames = expectOnlyCompleteFrames(out);
  EXPECT_GE(frames, 4);
  EXPECT_LT(frames, 400) << "it stopped";
}

// Two frames thousands of steps apart: Ctrl-C is checked between batches of
// steps inside a frame, not only between frames, so it stops at once.
TEST_F(MorphCli, CtrlCStopsALongFrameAtOnce)
{
  const fs::path out = folder / "frames";
  const fs::path log = folder / "stderr.txt";
  const pid_t pid = spawnLbmshape({"-q", "morph", sphere, torus, out.string(), "--res", "64", "--frames", "2",
                                   "--steps", "50000", "--format", "obj", "--no-animation"},
                                  log.string());
  ASSERT_GT(pid, 0);
  // Frame 0 is handed to the writer before the first step: once its file
  // exists the lattice is in the long frame (or about to enter it), which
  // the step in the message below proves.
  ASSERT_TRUE(waitForFile(out / "frame_0000.obj", std::chrono::seconds(60)));
  kill(pid, SIGINT);
  const int status = waitForExit(pid, std::chrono::seconds(120));  // a failing test must not hang
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_EQ(expectOnlyCompleteFrames(out), 1);
  // Had Ctrl-C waited for the frame's end, it would say step 50000.
  std::ifstream in(log);
  const std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = err.find("(at step ");
  ASSERT_NE(at, std::string::npos) << err;
  EXPECT_LT(std::stol(err.substr(at + 9)), 50000) << err;
  EXPECT_NE(err.find(" of 50000)"), std::string::npos) << err;
}

// One writer per folder: a second morph into a folder that a morph is
// writing fails at once (exit 4, naming the folder), even with --force, and
// the first one's frames are left alone.
TEST_F(MorphCli, ASecondMorphIntoTheSameFolderIsRefused)
{
  const fs::path out = folder / "frames";
  const pid_t pid = spawnLbmshape({"-q", "morph", sphere, torus, out.string(), "--res", "48", "--frames", "400",
                                   "--format", "obj", "--no-animation"});
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForFile(out / "frame_0001.obj", std::chrono::seconds(60)));
  testing::CliResult second =
      testing::runLbmshape({"-v", "morph", sphere, torus, out.string(), "--res", "32", "--frames", "3", "--force"});
  kill(pid, SIGINT);
  waitForExit(pid, std::chrono::seconds(60));
  EXPECT_EQ(second.exitCode, 4) << second.err;
  EXPECT_NE(second.err.find(out.string() + " is being written by another lbmshape"), std::string::npos) << second.err;
  EXPECT_EQ(second.err.find("sdf"), std::string::npos) << "refused before any work: " << second.err;
  EXPECT_GE(expectOnlyCompleteFrames(out), 2);
}

// Two morphs started together on a folder that does not exist yet: one
// makes and locks it before any work, the other is refused (exit 4, before
// any work), and the winner's frames are all there. Before, each took the
// folder for its own new one, the loser removed it while it was empty, and
// the winner could exit 0 with its frames gone.
TEST_F(MorphCli, TwoMorphsIntoOneNewFolderLeaveTheWinnersFrames)
{
  for (int attempt = 0; attempt < 4; ++attempt) {
    const fs::path out = folder / ("new" + std::to_string(attempt)) / "frames";
    const fs::path log = folder / ("first" + std::to_string(attempt) + ".txt");
    const pid_t first = spawnLbmshape({"-q", "morph", sphere, torus, out.string(), "--res", "32", "--frames", "6",
                                       "--format", "obj", "--no-animation"},
                                      log.string());
    ASSERT_GT(first, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(20 * attempt));
    testing::CliResult second = testing::runLbmshape({"-q", "morph", sphere, torus, out.string(), "--res", "24",
                                                      "--frames", "3", "--format", "obj", "--no-animation"});
    const int status = waitForExit(first, std::chrono::seconds(120));
    ASSERT_TRUE(WIFEXITED(status));
    const int firstCode = WEXITSTATUS(status);
    EXPECT_TRUE((firstCode == 0 && second.exitCode == 4) || (firstCode == 4 && second.exitCode == 0))
        << "attempt " << attempt << ": exits " << firstCode << " and " << second.exitCode << "\n"
        << second.err;
    const int frames = expectOnlyCompleteFrames(out);
    EXPECT_EQ(frames, firstCode == 0 ? 6 : 3) << "attempt " << attempt << ": the winner's frames, all of them";
  }
}

// A morph continued from another's frame into the same folder, with
// --force, would remove or replace its own source: refused before any work,
// the frame left as it was.
TEST_F(MorphCli, AnInputThatIsOneOfTheFoldersFramesIsRefused)
{
  const fs::path out = folder / "frames";
  fs::create_directories(out);
  const fs::path continued = out / "frame_0005.obj";
  fs::copy_file(sphere, continued);
  const auto before = fs::file_size(continued);
  testing::CliResult r = testing::runLbmshape(
      {"-v", "morph", continued.string(), torus, out.string(), "--res", "32", "--frames", "3", "--force"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("the source " + continued.string() + " is one of the files a morph writes"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("sdf"), std::string::npos) << "refused before any work: " << r.err;
  ASSERT_TRUE(fs::exists(continued));
  EXPECT_EQ(fs::file_size(continued), before);
  // Beside the frames, under a name of its own, it is a source like any other.
  const fs::path kept = out / "start.obj";
  fs::rename(continued, kept);
  EXPECT_EQ(testing::runLbmshape(
                {"-q", "morph", kept.string(), torus, out.string(), "--res", "32", "--frames", "3", "--force"})
                .exitCode,
            0);
  EXPECT_TRUE(fs::exists(kept));
}

// What the frames will not show by themselves is said on stderr: where
// --align put the target, frames that repeat the one before (a shape into
// itself: more frames than steps no longer repeat, morph_arrival_test.cpp),
// and a last frame whose parts differ from the target's (a part too small
// for the grid).
TEST_F(MorphCli, SaysWhereTheTargetWentWhenFramesRepeatAndWhatTheGridLost)
{
  const fs::path bigger = folder / "bigger.obj";
  writeMesh(testing::scaled(testing::torusMesh(1.0, 0.4, 48, 24), 3.0, glm::dvec3(0.0)), bigger);
  testing::CliResult fit = testing::runLbmshape(
      {"morph", sphere, bigger.string(), (folder / "fit").string(), "--res", "20", "--frames", "60"});
  ASSERT_EQ(fit.exitCode, 0) << fit.err;
  EXPECT_NE(fit.err.find("bigger.obj placed on the source (--align fit): scaled by 0.28"), std::string::npos)
      << fit.err;
  EXPECT_EQ(fit.err.find("repeat"), std::string::npos) << "more frames than steps take shorter steps: " << fit.err;
  EXPECT_EQ(fit.err.find("where the target has"), std::string::npos) << fit.err;
  // Given steps fewer than the intervals: frames repeat, and a warning
  // says how many (it was an info line, or nothing).
  const testing::CliResult few = testing::runLbmshape({"morph", sphere, bigger.string(), (folder / "few").string(),
                                                       "--res", "20", "--frames", "6", "--steps", "2", "-q"});
  ASSERT_EQ(few.exitCode, 0) << few.err;
  EXPECT_NE(few.err.find("warning: 3 of the 6 frames repeat the frame before: 2 steps are fewer than the 5 intervals"),
            std::string::npos)
      << few.err;
  // --fps says how fast morph.glb plays: with no morph.glb it means nothing.
  const testing::CliResult fps = testing::runLbmshape(
      {"morph", sphere, bigger.string(), (folder / "fps").string(), "--res", "20", "--no-animation", "--fps", "30"});
  EXPECT_EQ(fps.exitCode, 2) << fps.err;
  EXPECT_NE(fps.err.find("--fps excludes --no-animation"), std::string::npos) << fps.err;
  testing::CliResult itself =
      testing::runLbmshape({"morph", sphere, sphere, (folder / "itself").string(), "--res", "20", "--frames", "4"});
  ASSERT_EQ(itself.exitCode, 0) << itself.err;
  EXPECT_NE(itself.err.find("the morph takes no step, and all 4 frames are the same shape"), std::string::npos)
      << itself.err;

  // A target of two parts, one far smaller than a voxel: the last frame
  // has only the other.
  const fs::path twoParts = folder / "two_parts.obj";
  writeMesh(testing::merged(testing::icosphere(3), testing::icosphere(3, 0.01, {1.6, 0.0, 0.0})), twoParts);
  testing::CliResult lost = testing::runLbmshape({"morph", sphere, twoParts.string(), (folder / "lost").string(),
                                                  "--res", "24", "--frames", "3", "--align", "none", "--json"});
  ASSERT_EQ(lost.exitCode, 0) << lost.err;
  EXPECT_EQ(lost.err.find("placed on the source"), std::string::npos) << "--align none moves nothing: " << lost.err;
  const std::string partsLost = "the last frame has 1 part of genus 0 where the target has 2 parts of genus 0";
  EXPECT_NE(lost.err.find(partsLost), std::string::npos) << lost.err;
  // The report lists it too, for a script that keeps --json and drops stderr.
  const auto warnings = nlohmann::json::parse(lost.out)["warnings"];
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [&](const auto& w) {
    return w.template get<std::string>().find(partsLost) == 0;
  })) << warnings;
}

// morph.glb past the 4 GiB a .glb holds: refused at once, exit 4, nothing
// written (it failed only when it got there, minutes later, its frames
// left behind); --no-animation or --compress are offered.
TEST_F(MorphCli, AnAnimationPastWhatAGlbHoldsIsRefusedBeforeAnyWork)
{
  const fs::path out = folder / "many";
  const testing::CliResult r =
      testing::runLbmshape({"morph", sphere, torus, out.string(), "--res", "48", "--frames", "100000"});
  EXPECT_EQ(r.exitCode, 4) << r.err;
  const auto lines = testing::messageLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_NE(lines[0].find("past the 4 GiB a .glb holds; about "), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("--no-animation"), std::string::npos) << lines[0];
  EXPECT_FALSE(fs::exists(out)) << "nothing written";
}

// A shape less than a voxel across on the grid the two share is named with
// its size and the other's, and --align fit offered, before any distance:
// "it encloses no volume ... an open sheet has no inside" sent the user
// looking for holes in a closed mesh.
TEST_F(MorphCli, AShapeSmallerThanAVoxelIsNamedWithItsSize)
{
  const fs::path tiny = folder / "tiny.obj";
  writeMesh(testing::icosphere(2, 0.001), tiny);
  const testing::CliResult r = testing::runLbmshape(
      {"morph", sphere, tiny.string(), (folder / "out").string(), "--res", "16", "--align", "none"});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("cannot use " + tiny.string() + ": it is 0.002 across, less than a voxel"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--align fit scales the target onto the source"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("sdf"), std::string::npos) << "before the distances: " << r.err;
  EXPECT_NE(r.err.find(sphere + " (2 across) sets"), std::string::npos) << r.err;

  // Far from the sphere, the distance between them sets the grid, not the
  // sphere (the message named the sphere's size).
  const fs::path far = folder / "far.obj";
  writeMesh(testing::icosphere(2, 0.3, {1e3, 0.0, 0.0}), far);
  const testing::CliResult apart = testing::runLbmshape(
      {"morph", sphere, far.string(), (folder / "apart").string(), "--res", "16", "--align", "none"});
  EXPECT_EQ(apart.exitCode, 3) << apart.err;
  EXPECT_NE(apart.err.find("whose size the two shapes set together, lying apart"), std::string::npos) << apart.err;
}

// A folder that cannot be made is an output error before any work.
TEST_F(MorphCli, AFolderThatCannotBeMadeIsRefusedBeforeAnyWork)
{
  std::ofstream(folder / "file.txt") << "not a folder";
  const fs::path out = folder / "file.txt" / "frames";
  testing::CliResult r =
      testing::runLbmshape({"-v", "morph", sphere, torus, out.string(), "--res", "32", "--frames", "3"});
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_NE(r.err.find("is not a folder"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("sdf"), std::string::npos) << "refused before any work: " << r.err;
}

}  // namespace
}  // namespace lbmshape
