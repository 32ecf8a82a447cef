// lbmshape denoise, compare and noise as a user runs them: every bad input
// has its exit code, a one-line message and leaves no output file; good runs
// write meshes that the Khronos glTF-Validator accepts.
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/cli_runner.hpp"
#include "support/gltf_validator.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"
#include "lbmshape/surface/triangle_relaxation.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

struct BadInput {
  const char* name;
  int exitCode;
  // Prepares the folder; returns the input and output arguments.
  std::function<std::pair<std::string, std::string>(const fs::path&)> prepare;
  const char* mentions = "";  // the message must contain this, if given
};

void PrintTo(const BadInput& c, std::ostream* os) { *os << c.name; }

std::string sphereObj(const fs::path& folder)
{
  writeMesh(testing::icosphere(3), folder / "sphere.obj");
  return (folder / "sphere.obj").string();
}

class DenoiseBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(DenoiseBadInput, ExitCodeOneLineNoOutput)
{
  testing::ScratchFolder folder;
  auto [input, output] = GetParam().prepare(folder.path());
  const auto before = folder.entries();
  testing::CliResult r = testing::runLbmshape({"denoise", input, output, "--res", "24"});
  EXPECT_EQ(r.exitCode, GetParam().exitCode) << r.err;
  auto lines = testing::messageLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_EQ(lines[0].rfind("lbmshape: error: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(GetParam().mentions), std::string::npos) << lines[0];
  EXPECT_EQ(folder.entries(), before) << "no output, no temporary file left behind";
  EXPECT_TRUE(r.out.empty());
}

INSTANTIATE_TEST_SUITE_P(
    Table, DenoiseBadInput,
    ::testing::Values(BadInput{"missing_file", 3,
                               [](const fs::path& f) {
                                 return std::pair{(f / "nothing.obj").string(), (f / "out.glb").string()};
                               }},
                      BadInput{"empty_file", 3,
                               [](const fs::path& f) {
                                 writeText(f / "empty.obj", "");
                                 return std::pair{(f / "empty.obj").string(), (f / "out.glb").string()};
                               }},
                      BadInput{"binary_garbage_named_obj", 3,
                               [](const fs::path& f) {
                                 std::string junk;
                                 for (int i = 0; i < 4096; ++i) junk += char((i * 7919 + 13) % 256);
                                 writeText(f / "junk.obj", junk);
                                 return std::pair{(f / "junk.obj").string(), (f / "out.glb").string()};
                               }},
                      BadInput{"nan_coordinates", 3,
                               [](const fs::path& f) {
                                 writeText(
                                     f / "nan.obj",
                                     "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n");
                                 return std::pair{(f / "nan.obj").string(), (f / "out.glb").string()};
                               }},
                      BadInput{"single_triangle", 3,
                               [](const fs::path& f) {
                                 writeText(f / "one.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
                                 return std::pair{(f / "one.obj").string(), (f / "out.glb").string()};
                               }},
                      BadInput{"zero_area_bounding_box", 3,
                               [](const fs::path& f) {
                                 writeText(f / "line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 2 3 4\n");
                                 return std::pair{(f / "line.obj").string(), (f / "out.glb").string()};
                               }},
                      BadInput{"flat_mesh", 3,
                               [](const fs::path& f) {
                                 writeText(f / "flat.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n");
                                 return std::pair{(f / "flat.obj").string(), (f / "out.glb").string()};
                               }},
                      // Open sheets that are not flat: the winding number stays below 1/2
                      // everywhere, so nothing is inside. Before any smoothing, and the
                      // input is to blame, not the smoothing (exit 3, not 5).
                      BadInput{"open_sheet_bent_into_a_half_cylinder", 3,
                               [](const fs::path& f) {
                                 // Triangles facing the axis: the concave side is outside.
                                 writeMesh(testing::sheet(16,
                                                          [](double u, double v) {
                                                            const double a = std::numbers::pi * (1.0 - u);
                                                            return glm::dvec3(std::cos(a), std::sin(a), 4.0 * v);
                                                          }),
                                           f / "gutter.obj");
                                 return std::pair{(f / "gutter.obj").string(), (f / "out.glb").string()};
                               },
                               "gutter.obj: it encloses no volume"},
                      BadInput{"open_wavy_square", 3,
                               [](const fs::path& f) {
                                 writeMesh(testing::sheet(16,
                                                          [](double u, double v) {
                                                            return glm::dvec3(
                                                                u, v, 0.01 * std::sin(7.0 * u) * std::cos(5.0 * v));
                                                          }),
                                           f / "square.obj");
                                 return std::pair{(f / "square.obj").string(), (f / "out.glb").string()};
                               },
                               "square.obj: it encloses no volume"},
                      BadInput{"missing_output_folder", 4,
                               [](const fs::path& f) {
                                 return std::pair{sphereObj(f), (f / "no" / "such" / "out.glb").string()};
                               }},
                      BadInput{"output_folder_is_a_file", 4,
                               [](const fs::path& f) {
                                 writeText(f / "afile", "x");
                                 return std::pair{sphereObj(f), (f / "afile" / "out.glb").string()};
                               }},
                      BadInput{"unknown_output_extension", 2,
                               [](const fs::path& f) {
                                 return std::pair{sphereObj(f), (f / "out.xyz").string()};
                               }},
                      BadInput{"unknown_input_extension", 3,
                               [](const fs::path& f) {
                                 writeText(f / "mesh.xyz", "v 0 0 0\n");
                                 return std::pair{(f / "mesh.xyz").string(), (f / "out.glb").string()};
                               }}),
    [](const auto& info) { return std::string(info.param.name); });

// Relaxation evens out marching cubes' triangles (surface/triangle_relaxation.hpp)
// and leaves the surface where it is: by default 2 rounds, reported, and
// --relax 0 gives marching cubes' own triangles.
TEST(DenoiseCli, TheTrianglesAreRelaxedUnlessRelaxIsZero)
{
  testing::ScratchFolder folder;
  const fs::path input = folder / "torus.obj";
  writeMesh(testing::torusMesh(1.0, 0.4, 96, 48), input);
  std::map<std::string, nlohmann::json> reports;
  for (const std::string rounds : {"0", "default", "3"}) {
    std::vector<std::string> args = {
        "denoise", input.string(), (folder / (rounds + ".obj")).string(), "--res", "48", "--steps", "3", "--json"};
    if (rounds != "default") args.insert(args.end(), {"--relax", rounds});
    testing::CliResult r = testing::runLbmshape(args);
    ASSERT_EQ(r.exitCode, 0) << rounds << ": " << r.err;
    reports[rounds] = nlohmann::json::parse(r.out);
  }
  EXPECT_EQ(reports["0"]["relax_rounds"], 0);
  EXPECT_EQ(reports["default"]["relax_rounds"], defaultRelaxationRounds);
  EXPECT_EQ(reports["3"]["relax_rounds"], 3);
  EXPECT_FALSE(reports["0"]["ms"].contains("relax"));
  EXPECT_TRUE(reports["default"]["ms"].contains("relax"));
  const TriangleMesh raw = readMesh(folder / "0.obj"), relaxed = readMesh(folder / "default.obj");
  // The same triangles, moved (TriangleRelaxation.* checks them one by one
  // in a process; these are two).
  ASSERT_EQ(raw.triangleCount(), relaxed.triangleCount()) << reports["0"] << "\n" << reports["default"];
  auto slivers = [](const TriangleMesh& m) { return testing::triangleCountWithAngleUnder(m, 10.0); };
  EXPECT_GT(slivers(raw), raw.triangleCount() / 50);
  EXPECT_LT(slivers(relaxed), slivers(raw) / 5);
  // The surface stayed: the two lie within a hundredth of a voxel of each
  // other on average.
  const double voxel = reports["0"]["grid"]["voxel"].get<double>();
  EXPECT_LT(compareSurfaces(raw, relaxed, ComparisonOptions{20000}).mean, 0.01 * voxel);
  // Marching cubes' facets are chords, inside the surface; evened out, they
  // cut less off it: the volume comes nearer the input's (here 1.0 % below
  // it before, 0.9 % after), by a fraction of a percent.
  const double inputVolume = analyzeTopology(readMesh(input)).signedVolume;
  const double before = reports["0"]["output"]["volume"].get<double>();
  const double after = reports["default"]["output"]["volume"].get<double>();
  EXPECT_LT(std::abs(after - inputVolume), std::abs(before - inputVolume));
  EXPECT_NEAR(after, before, 5e-3 * before);
}

TEST(DenoiseCli, BadParametersAreUsageErrors)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path()), output = (folder / "out.glb").string();
  for (std::vector<std::string> extra : {std::vector<std::string>{"--gamma", "0"},
                                         {"--gamma", "-1"},
                                         {"--steps", "-2"},
                                         {"--res", "2"},
                                         {"--voxel", "-0.1"},
                                         {"--voxel", "0"},
                                         {"--voxel", "nan"},
                                         {"--voxel", "inf"},
                                         {"--noise", "-0.5"},
                                         {"--anisotropic", "--preserve-features"},
                                         {"--isotropic", "--preserve-features"},
                                         {"--isotropic", "--anisotropic"},
                                         {"--res", "64", "--voxel", "0.1"},
                                         {"--radius", "0"},
                                         {"--radius", "-0.1"},
                                         {"--radius", "nan"},
                                         {"--radius", "100"},
                                         {"--radius", "0.3", "--voxel", "0.001"},
                                         {"--radius", "0.1", "--steps", "3"},
                                         {"--relax", "-1"},
                                         {"--relax", "101"},
                                         {"--relax", "two"}}) {
    std::vector<std::string> args = {"denoise", input, output};
    args.insert(args.end(), extra.begin(), extra.end());
    testing::CliResult r = testing::runLbmshape(args);
    EXPECT_EQ(r.exitCode, 2) << extra[0] << " " << r.err;
    auto lines = testing::nonEmptyLines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_NE(lines[0].find(extra[0]), std::string::npos) << "the message names the option: " << lines[0];
    EXPECT_FALSE(fs::exists(output));
  }
}

// --radius says how much to smooth in the mesh's units: the report says
// so, with the steps it took on this grid, and a finer grid takes more.
TEST(DenoiseCli, RadiusChoosesTheStepsForTheGrid)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path()), output = (folder / "out.glb").string();
  int previous = 0;
  for (const char* res : {"24", "48"}) {
    testing::CliResult r =
        testing::runLbmshape({"denoise", input, output, "--res", res, "--radius", "0.1", "--json", "--force"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json report = nlohmann::json::parse(r.out);
    EXPECT_EQ(report["steps_chosen"], "radius");
    EXPECT_EQ(report["radius"], 0.1);
    const int steps = report["steps"];
    EXPECT_GT(steps, 2 * previous) << "--res " << res;
    previous = steps;
  }
}

// Feature-preserving smoothing is the default (docs/denoising.md, "How good
// it is"); the paper's isotropic scheme and its anisotropic rule are flags.
TEST(DenoiseCli, SmoothingPreservesFeaturesUnlessAskedOtherwise)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path()), output = (folder / "out.glb").string();
  for (const auto& [flag, smoothing] : std::vector<std::pair<std::string, std::string>>{
           {"", "preserve-features"}, {"--isotropic", "isotropic"}, {"--anisotropic", "anisotropic"}}) {
    std::vector<std::string> args = {"denoise", input, output, "--res", "24", "--steps", "2", "--json", "--force"};
    if (!flag.empty()) args.push_back(flag);
    testing::CliResult r = testing::runLbmshape(args);
    ASSERT_EQ(r.exitCode, 0) << flag << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["smoothing"], smoothing) << flag;
    // steps_run counts every lattice step, the edge-finding copy's too (so
    // MLUPS are the lattice's): more than the 2 kept by default.
    if (flag.empty())
      EXPECT_GT(j["steps_run"].get<int>(), 2);
    else
      EXPECT_EQ(j["steps_run"], 2) << flag;
  }
}

// --twicing runs the smoothing twice (docs/denoising.md, "Twicing"); by
// default only where the noise needs it, never with given steps.
TEST(DenoiseCli, TwicingIsAFlagThatDoublesTheSmoothingsSteps)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path()), output = (folder / "out.glb").string();
  for (const bool twicing : {false, true}) {
    std::vector<std::string> args = {"denoise", input, output,        "--res",  "24",
                                     "--steps", "3",   "--isotropic", "--json", "--force"};
    if (twicing) args.push_back("--twicing");
    testing::CliResult r = testing::runLbmshape(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["twicing"], twicing);
    EXPECT_EQ(j["steps"], 3);
    EXPECT_EQ(j["steps_run"], twicing ? 6 : 3);
    EXPECT_EQ(j["twicing_chosen"], twicing ? "given" : "auto");
  }
  // --no-twicing: never twiced (a choice, not the default's automatic one);
  // told both ways, a usage error.
  testing::CliResult never =
      testing::runLbmshape({"denoise", input, output, "--res", "24", "--no-twicing", "--json", "--force"});
  ASSERT_EQ(never.exitCode, 0) << never.err;
  EXPECT_EQ(nlohmann::json::parse(never.out)["twicing"], false);
  EXPECT_EQ(nlohmann::json::parse(never.out)["twicing_chosen"], "given");
  testing::CliResult both =
      testing::runLbmshape({"denoise", input, output, "--res", "24", "--twicing", "--no-twicing", "--force"});
  EXPECT_EQ(both.exitCode, 2) << both.err;
}

TEST(DenoiseCli, WritesValidGltfAndReportsJson)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path());
  for (const char* name : {"out.glb", "out.gltf"}) {
    const fs::path output = folder / name;
    testing::CliResult r = testing::runLbmshape({"denoise", input, output.string(), "--res", "32", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    for (const char* key : {"input", "output", "grid", "gamma", "steps", "ms", "mlups", "volume_change", "device"})
      EXPECT_TRUE(j.contains(key)) << key;
    for (const char* stage : {"read", "sdf", "lbm", "extract", "write", "total"})
      EXPECT_TRUE(j["ms"].contains(stage)) << stage;
    // The device's busy time within each stage, from timestamps: some in the
    // lattice stage, and never more than the stage's wall time.
    ASSERT_TRUE(j["device_ms"].is_object());
    EXPECT_GT(j["device_ms"].value("lbm", 0.0), 0.0) << j["device_ms"];
    for (const auto& [stage, ms] : j["device_ms"].items())
      EXPECT_LE(ms.get<double>(), j["ms"][stage].get<double>()) << stage;
    EXPECT_TRUE(j["output"]["closed_manifold"].get<bool>());
    EXPECT_LT(std::abs(j["volume_change"].get<double>()), 0.1);
    const auto validation = testing::validateGltf(output);
    EXPECT_TRUE(validation.passed()) << validation;
  }
}

// --sdf: the band's distances on the CPU or on the device give the same
// mesh. Within 3 voxels of the surface the two distances agree to float
// rounding; beyond, the CPU's are propagated and up to 0.08 voxel longer
// than the exact ones the device computes (the sphere's and torus's
// medial regions: tests/sdf/device_band_distances_test.cpp), which three
// lattice steps carry some way towards the surface. So the meshes agree to
// a small fraction of a voxel at worst and to 1e-4 voxel on average.
// auto takes the CPU on a CPU device (lavapipe), the device on a GPU.
TEST(DenoiseCli, TheDistancesOnTheDeviceGiveTheSameMesh)
{
  testing::ScratchFolder folder;
  const std::string input = (folder / "torus.obj").string();
  writeMesh(testing::torusMesh(1.0, 0.3, 96, 32), input);
  std::map<std::string, nlohmann::json> reports;
  for (const std::string where : {"cpu", "device", "auto"}) {
    const std::string output = (folder / (where + ".glb")).string();
    testing::CliResult r =
        // --relax 0: the fields' surfaces (relaxation, the same code after
        // either, may keep a vertex in one and move it in the other).
        testing::runLbmshape(
            {"denoise", input, output, "--res", "48", "--steps", "3", "--sdf", where, "--relax", "0", "--json"});
    ASSERT_EQ(r.exitCode, 0) << where << ": " << r.err;
    reports[where] = nlohmann::json::parse(r.out);
  }
  EXPECT_EQ(reports["cpu"]["sdf_on"], "cpu");
  EXPECT_EQ(reports["device"]["sdf_on"], "device");
  EXPECT_EQ(reports["auto"]["sdf_on"],
            reports["auto"]["device"].get<std::string>().find("llvmpipe") == 0 ? "cpu" : "device");
  testing::CliResult compared =
      testing::runLbmshape({"compare", (folder / "cpu.glb").string(), (folder / "device.glb").string(), "--json"});
  ASSERT_EQ(compared.exitCode, 0) << compared.err;
  const auto c = nlohmann::json::parse(compared.out);
  const double voxel = reports["cpu"]["grid"]["voxel"].get<double>();
  EXPECT_LT(c["hausdorff"].get<double>(), 0.05 * voxel) << c;
  EXPECT_LT(c["mean"].get<double>(), 1e-3 * voxel) << c;
  EXPECT_EQ(reports["cpu"]["output"]["triangles"], reports["device"]["output"]["triangles"]);
}

TEST(DenoiseCli, SdfIsCpuDeviceOrAuto)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path()), output = (folder / "out.glb").string();
  testing::CliResult r = testing::runLbmshape({"denoise", input, output, "--sdf", "gpu"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  const auto lines = testing::nonEmptyLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_NE(lines[0].find("--sdf"), std::string::npos) << lines[0];
  EXPECT_FALSE(fs::exists(output));
  r = testing::runLbmshape({"denoise", input, output, "--sdf", "device", "--device", "reference"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--sdf device"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(output));
  // The grid has no distances on the device: it says so, and runs.
  r = testing::runLbmshape({"denoise", input, output, "--sdf", "device", "--dense", "--res", "24", "--json"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("warning: --sdf device computes the narrow band's distances"), std::string::npos) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["sdf_on"], "cpu");
}

// A band larger than the device is refused as soon as its bricks are known,
// with what would fit; the limits themselves are tested in
// tests/lbm/band_memory_test.cpp. A sphere's band at --res 1200 holds about
// 1e8 cells (3.7 GB on the device): past lavapipe's 2 GiB heap, within a
// large GPU's.
TEST(DenoiseCli, ABandTooLargeForTheDeviceIsRefusedBeforeItsDistances)
{
  const auto info = nlohmann::json::parse(testing::runLbmshape({"info", "--json"}).out);
  const auto& device = info["devices"][info["selected"].get<size_t>()];
  if (device["device_local_bytes"].get<uint64_t>() > (uint64_t(3) << 30))
    GTEST_SKIP() << device["name"] << " has room for this band; the refusal is tested on lavapipe";
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path());
  const auto before = folder.entries();
  // --quiet: on a busy machine, choosing the bricks may take long enough to show progress.
  for (std::vector<std::string> args : {std::vector<std::string>{"-q", "denoise", input, (folder / "out.glb").string()},
                                        {"-q", "morph", input, input, (folder / "frames").string()}}) {
    args.insert(args.end(), {"--res", "1200"});
    testing::CliResult r = testing::runLbmshape(args);
    EXPECT_EQ(r.exitCode, 5) << args[1] << ": " << r.err;
    auto lines = testing::nonEmptyLines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_NE(lines[0].find("narrow band"), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("would fit"), std::string::npos) << lines[0];
    EXPECT_EQ(folder.entries(), before) << args[1] << " wrote nothing";
  }
}

// On a device that is the CPU a band meets two limits, the device's and the
// host's (here an address-space limit): the grid a refusal names fits both.
// It used to name the device's alone (--res 781 under ulimit -v 800000),
// which the host's check then refused, naming another.
TEST(DenoiseCli, TheGridARefusalNamesFitsEveryLimit)
{
  LBMSHAPE_SKIP_WITHOUT_ADDRESS_SPACE_LIMITS();
  const auto info = nlohmann::json::parse(testing::runLbmshape({"info", "--json"}).out);
  const auto& device = info["devices"][info["selected"].get<size_t>()];
  if (device["type"] != "cpu") GTEST_SKIP() << device["name"] << " is no CPU: the host's memory is not its limit";
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path()), output = (folder / "out.glb").string();
  const testing::CliResult refused = testing::runLbmshapeWithin(600, {"-q", "denoise", input, output, "--res", "1200"});
  ASSERT_EQ(refused.exitCode, 5) << refused.err;
  const size_t at = refused.err.find("(--res ");
  ASSERT_NE(at, std::string::npos) << refused.err;
  const std::string named = std::to_string(std::stoi(refused.err.substr(at + 7)));
  const testing::CliResult fits =
      testing::runLbmshapeWithin(600, {"-q", "denoise", input, output, "--res", named, "--steps", "0"});
  EXPECT_EQ(fits.exitCode, 0) << "--res " << named << ", named by: " << refused.err << "\n" << fits.err;
}

// Writing over the input mesh, by its own path or through a link, is
// refused before any work unless asked for with --force.
TEST(DenoiseCli, WarnsOnlyWhenGammaAndStepsAreOutsideTheAccurateRange)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path());
  const std::string output = (folder.path() / "out.glb").string();
  const testing::CliResult defaults = testing::runLbmshape({"denoise", input, output, "--res", "24", "--force"});
  ASSERT_EQ(defaults.exitCode, 0) << defaults.err;
  EXPECT_EQ(defaults.err.find("warning"), std::string::npos) << defaults.err;

  const testing::CliResult fewSteps =
      testing::runLbmshape({"denoise", input, output, "--res", "24", "--gamma", "1", "--steps", "3", "--force"});
  ASSERT_EQ(fewSteps.exitCode, 0) << fewSteps.err;
  std::vector<std::string> warnings;
  for (const std::string& line : testing::nonEmptyLines(fewSteps.err))
    if (line.rfind("lbmshape: warning: ", 0) == 0) warnings.push_back(line);
  ASSERT_EQ(warnings.size(), 1u) << fewSteps.err;
  EXPECT_NE(warnings[0].find("--gamma = 1 over 3 steps smooths 61.8 % less than the diffusion equation"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("more steps at a smaller --gamma"), std::string::npos) << warnings[0];

  // --json's report lists the warnings too, for a script that drops stderr;
  // in a jobs file, each job's report its own.
  const testing::CliResult json = testing::runLbmshape(
      {"denoise", input, output, "--res", "24", "--gamma", "1", "--steps", "3", "--force", "--json"});
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const auto report = nlohmann::json::parse(json.out);
  ASSERT_EQ(report["warnings"].size(), 1u) << report["warnings"];
  EXPECT_EQ("lbmshape: warning: " + report["warnings"][0].get<std::string>(), warnings[0]);
  const testing::CliResult quiet = testing::runLbmshape({"denoise", input, output, "--res", "24", "--force", "--json"});
  ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_EQ(nlohmann::json::parse(quiet.out)["warnings"], nlohmann::json::array());
  const fs::path jobs = folder / "jobs.json";
  std::ofstream(jobs) << nlohmann::json::array(
      {{{"command", "denoise"}, {"input", input}, {"output", output}, {"res", 24}, {"gamma", 1}, {"steps", 3}},
       {{"command", "denoise"}, {"input", input}, {"output", output + ".obj"}, {"res", 24}}});
  const testing::CliResult run = testing::runLbmshape({"run", jobs.string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto results = nlohmann::json::parse(run.out)["results"];
  EXPECT_EQ(results[0]["report"]["warnings"].size(), 1u) << results[0]["report"]["warnings"];
  EXPECT_EQ(results[1]["report"]["warnings"].size(), 0u) << results[1]["report"]["warnings"];
}

// A ring thinner than the grid resolves vanishes in the smoothing: the user
// is told, and told the way back (a finer grid). Not for a mesh that
// overlaps itself, whose union encloses less than its triangles count.
TEST(DenoiseCli, WarnsWhenThinPartsVanishOnACoarseGrid)
{
  testing::ScratchFolder folder;
  writeMesh(testing::torusMesh(1.0, 0.12, 96, 24), folder / "ring.obj");
  writeMesh(testing::merged(testing::icosphere(3), testing::icosphere(3, 1.0, {0.8, 0.0, 0.0})),
            folder / "overlapping.obj");
  const auto warned = [&](const std::string& mesh, const std::string& res) {
    const testing::CliResult r =
        testing::runLbmshape({"denoise", (folder / mesh).string(), (folder / "out.glb").string(), "--res", res, "-q"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.err.find("volume than the input: parts thinner than about two voxels") != std::string::npos &&
           r.err.find("a finer --res keeps them") != std::string::npos;
  };
  EXPECT_TRUE(warned("ring.obj", "24")) << "a ring 1.6 voxels thick";
  EXPECT_FALSE(warned("ring.obj", "96"));
  EXPECT_FALSE(warned("overlapping.obj", "48"));
  // Two overlapping spheres become their union, one part: not a part lost
  // (the bundled bolt, a head and a shaft that overlap, said so).
  const testing::CliResult united = testing::runLbmshape(
      {"denoise", (folder / "overlapping.obj").string(), (folder / "out.glb").string(), "--res", "48", "-v"});
  ASSERT_EQ(united.exitCode, 0) << united.err;
  EXPECT_EQ(united.err.find("where the input has"), std::string::npos) << united.err;
  EXPECT_NE(united.err.find("the input's 2 parts overlap: the result is their union, 1 part"), std::string::npos)
      << united.err;
  // The warning's figure is --json's volume_change.
  const testing::CliResult r = testing::runLbmshape(
      {"denoise", (folder / "ring.obj").string(), (folder / "out.glb").string(), "--res", "24", "-q", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const double change = nlohmann::json::parse(r.out)["volume_change"].get<double>();
  const std::string percent = "encloses " + std::to_string(int(std::lround(std::abs(change) * 100.0))) + " % less";
  EXPECT_NE(r.err.find(percent), std::string::npos) << percent << " in " << r.err;
}

// An open input (a sphere with its cap cut off) is closed by the result:
// said, with the number of open edges --json gives, where a closed one says
// nothing; an unwelded closed mesh (every triangle its own corners) is not
// open once joined.
TEST(DenoiseCli, SaysWhenTheResultClosesAnOpenInput)
{
  testing::ScratchFolder folder;
  const TriangleMesh sphere = testing::icosphere(3);
  TriangleMesh cut = sphere, soup;
  cut.triangles.clear();
  for (const auto& t : sphere.triangles)
    if (sphere.positions[t[0]].z + sphere.positions[t[1]].z + sphere.positions[t[2]].z < 1.8)
      cut.triangles.push_back(t);
  for (const auto& t : sphere.triangles) {
    const uint32_t first = uint32_t(soup.positions.size());
    for (int k = 0; k < 3; ++k) soup.positions.push_back(sphere.positions[t[k]]);
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  writeMesh(sphere, folder / "closed.obj");
  writeMesh(cut, folder / "cut.obj");
  writeMesh(soup, folder / "soup.obj");
  const auto run = [&](const char* mesh) {
    return testing::runLbmshape(
        {"denoise", (folder / mesh).string(), (folder / "out.glb").string(), "--res", "32", "--json"});
  };
  const testing::CliResult open = run("cut.obj");
  ASSERT_EQ(open.exitCode, 0) << open.err;
  const size_t openEdges = nlohmann::json::parse(open.out)["input"]["boundary_edges"];
  ASSERT_GT(openEdges, 0u);
  EXPECT_NE(open.err.find("cut.obj is open (" + std::to_string(openEdges) + " edges in one triangle only"),
            std::string::npos)
      << open.err;
  EXPECT_NE(open.err.find("the result closes it"), std::string::npos) << open.err;
  for (const char* closed : {"closed.obj", "soup.obj"}) {
    const testing::CliResult r = run(closed);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("is open"), std::string::npos) << closed << ": " << r.err;
  }
}

TEST(DenoiseCli, TheOutputIsNotTheInputUnlessForced)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path());
  const fs::path link = folder / "link.obj";
  fs::create_symlink(input, link);
  const auto before = fs::file_size(input);
  for (std::vector<std::string> args : {std::vector<std::string>{"denoise", input, input, "--res", "24"},
                                        {"denoise", input, link.string(), "--res", "24"},
                                        {"noise", input, input, "--sigma", "0.1"}}) {
    testing::CliResult r = testing::runLbmshape(args);
    EXPECT_EQ(r.exitCode, 2) << args[0] << ": " << r.err;
    EXPECT_NE(r.err.find("is the input mesh"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
    EXPECT_EQ(fs::file_size(input), before) << "the input is untouched";
  }
  testing::CliResult forced = testing::runLbmshape({"denoise", input, input, "--res", "24", "--force"});
  EXPECT_EQ(forced.exitCode, 0) << forced.err;
  EXPECT_NE(fs::file_size(input), before) << "--force replaced it";
}

TEST(CompareCli, IdenticalMeshesAreAtDistanceZero)
{
  testing::ScratchFolder folder;
  const std::string a = sphereObj(folder.path());
  testing::CliResult r = testing::runLbmshape({"compare", a, a, "--json", "--samples", "2000"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["hausdorff"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["mean_normal_angle_deg"].get<double>(), 0.0, 1e-6);
  EXPECT_EQ(j["a"]["genus"], 0);
  EXPECT_EQ(j["a"]["boundary_edges"], 0);
  EXPECT_TRUE(j["b"]["closed_manifold"].get<bool>());
}

// compare reports topology as denoise reads the mesh: a glTF split into a
// primitive per material (each numbering its seam's vertices) is one
// closed surface, not "2 components, 414 boundary edges"; the distances
// are the meshes' as they are.
TEST(CompareCli, ASurfaceInPiecesNumberedApartIsReportedWhole)
{
  testing::ScratchFolder folder;
  TriangleMesh split = testing::upperHalf(testing::icosphere(3));
  const TriangleMesh lower = testing::lowerHalf(testing::icosphere(3));
  const auto offset = uint32_t(split.positions.size());
  split.positions.insert(split.positions.end(), lower.positions.begin(), lower.positions.end());
  for (const glm::uvec3& t : lower.triangles) split.triangles.push_back(t + offset);
  const std::string path = (folder / "split.obj").string(), whole = sphereObj(folder.path());
  writeMesh(split, path);
  testing::CliResult r = testing::runLbmshape({"compare", path, whole, "--json", "--samples", "2000"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["a"]["closed_manifold"].get<bool>());
  EXPECT_EQ(j["a"]["components"], 1);
  EXPECT_EQ(j["a"]["boundary_edges"], 0);
  EXPECT_GT(j["a"]["joined_vertices"].get<int>(), 0);
  EXPECT_EQ(j["b"]["joined_vertices"], 0);
  EXPECT_LT(j["hausdorff"].get<double>(), 1e-6);
  r = testing::runLbmshape({"compare", path, whole, "--samples", "2000"});
  EXPECT_NE(r.out.find("vertices at the positions of others joined to them, as denoise joins them"), std::string::npos)
      << r.out;
}

// Samples that would not fit the host's memory are refused before any is
// taken, naming the --samples that would (10 million under a 300 MB
// address-space limit ran out of memory, exit 5 with no advice).
TEST(CompareCli, SamplesThatCannotFitAreRefusedWithWhatWould)
{
  LBMSHAPE_SKIP_WITHOUT_ADDRESS_SPACE_LIMITS();
  testing::ScratchFolder folder;
  const std::string a = sphereObj(folder.path());
  // 10 million (the most --samples takes) need about 1 GB; 300 MB of
  // address space leaves lbmshape about 200.
  const testing::CliResult r = testing::runLbmshapeWithin(300, {"compare", a, a, "--samples", "10000000"});
  EXPECT_EQ(r.exitCode, 5);
  const std::string& message = r.err;
  EXPECT_NE(message.find("comparing with 100"), std::string::npos) << message;  // 10,000,000 and the vertices
  const size_t advice = message.find("--samples ");
  ASSERT_NE(advice, std::string::npos) << message;
  const long fits = std::stol(message.substr(advice + 10));
  EXPECT_GT(fits, 100000);
  EXPECT_LT(fits, 10000000);
  EXPECT_NE(message.find("would fit"), std::string::npos) << message;
}

// compare and noise need no inside: a flat sheet (and a single triangle)
// is measured and made noisy, where denoise refuses it ("encloses no
// volume"); both were refused.
TEST(CompareCli, FlatMeshesAreComparedAndMadeNoisy)
{
  testing::ScratchFolder folder;
  const auto flat = (folder / "flat.obj").string(), wavy = (folder / "wavy.obj").string(),
             single = (folder / "single.obj").string();
  writeMesh(testing::sheet(8, [](double u, double v) { return glm::dvec3(u, v, 0.0); }), flat);
  writeMesh(testing::sheet(8, [](double u, double v) { return glm::dvec3(u, v, 0.05 * std::sin(6.0 * u)); }), wavy);
  TriangleMesh triangle;
  triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  triangle.triangles = {{0, 1, 2}};
  writeMesh(triangle, single);
  const testing::CliResult r = testing::runLbmshape({"compare", flat, wavy, "--json", "--samples", "2000"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["hausdorff"].get<double>(), 0.05, 0.01);
  EXPECT_GT(j["a"]["boundary_edges"].get<int>(), 0);
  EXPECT_EQ(testing::runLbmshape({"compare", single, flat}).exitCode, 0);
  const testing::CliResult noisy =
      testing::runLbmshape({"noise", flat, (folder / "noisy.obj").string(), "--sigma", "0.2"});
  EXPECT_EQ(noisy.exitCode, 0) << noisy.err;
  const testing::CliResult refused = testing::runLbmshape({"denoise", flat, (folder / "out.glb").string()});
  EXPECT_EQ(refused.exitCode, 3);
  EXPECT_NE(refused.err.find("encloses no volume"), std::string::npos) << refused.err;
}

TEST(NoiseCli, WritesANoisyCopyAndIsRepeatable)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path());
  for (const char* name : {"a.obj", "b.obj"})
    ASSERT_EQ(
        testing::runLbmshape({"noise", input, (folder / name).string(), "--sigma", "0.3", "--seed", "5"}).exitCode, 0);
  auto compare = [&](const std::string& x, const std::string& y) {
    return nlohmann::json::parse(testing::runLbmshape({"compare", x, y, "--json", "--samples", "2000"}).out);
  };
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(folder / "a.obj"), bytes(folder / "b.obj")) << "the same seed gives the same mesh";
  EXPECT_GT(compare(input, (folder / "a.obj").string())["mean"].get<double>(), 0.0);
}

TEST(NoiseCli, WithResSigmaIsInVoxelsOfDenoisesGrid)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path());
  const testing::CliResult r =
      testing::runLbmshape({"noise", input, (folder / "n.obj").string(), "--sigma", "0.5", "--res", "40", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto noise = nlohmann::json::parse(r.out);
  const testing::CliResult d =
      testing::runLbmshape({"denoise", input, (folder / "d.obj").string(), "--res", "40", "--steps", "0", "--json"});
  ASSERT_EQ(d.exitCode, 0) << d.err;
  const double voxel = nlohmann::json::parse(d.out)["grid"]["voxel"].get<double>();
  EXPECT_EQ(noise["sigma_unit"], "voxel");
  EXPECT_NEAR(noise["sigma_absolute"].get<double>(), 0.5 * voxel, 1e-12 * voxel);
  // And that is the noise the mesh gets: of its thousands of vertices some
  // move by more than one sigma.
  const auto c = nlohmann::json::parse(
      testing::runLbmshape({"compare", input, (folder / "n.obj").string(), "--json", "--samples", "20000"}).out);
  EXPECT_GT(c["hausdorff"].get<double>(), 0.5 * voxel);
  EXPECT_EQ(testing::runLbmshape({"noise", input, (folder / "m.obj").string(), "--res", "3"}).exitCode, 2);
}

TEST(NoiseCli, SigmaThatIsNotAFiniteSizeIsAUsageError)
{
  testing::ScratchFolder folder;
  const std::string input = sphereObj(folder.path());
  const fs::path output = folder / "noisy.obj";
  for (const char* sigma : {"-1", "nan", "inf", "-inf"}) {
    testing::CliResult r = testing::runLbmshape({"noise", input, output.string(), "--sigma", sigma, "--seed", "1"});
    EXPECT_EQ(r.exitCode, 2) << sigma << ": " << r.err;
    auto lines = testing::nonEmptyLines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0].rfind("lbmshape: error: --sigma must be a finite", 0), 0u) << lines[0];
    EXPECT_FALSE(fs::exists(output)) << sigma;
  }
}

}  // namespace
}  // namespace lbmshape
