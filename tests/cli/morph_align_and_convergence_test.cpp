// Where the target is placed (--align center and fit: the report's "align"
// and where the last frame lands, in the source's coordinates), and what a
// morph that converges early logs and writes.
#include <algorithm>
#include <fstream>
#include <iterator>
#include <regex>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

fs::path framePath(const fs::path& folder, int k)
{
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.obj", k);
  return folder / name;
}

// A unit sphere at the origin becomes a 4 x 4 x 3 box far from it, in
// another place and size: only the alignment brings it over the sphere.
class MorphAlign : public ::testing::TestWithParam<std::string> {
protected:
  testing::ScratchFolder folder;
  TriangleMesh sphere = testing::icosphere(3, 1.0);
  TriangleMesh box = testing::box({8, -1, -2}, {12, 3, 1});
  void SetUp() override
  {
    writeMesh(sphere, folder / "sphere.obj");
    writeMesh(box, folder / "box.obj");
  }
};

TEST_P(MorphAlign, TargetLandsOnTheSourceInItsCoordinates)
{
  const bool fit = GetParam() == "fit";
  const fs::path out = folder / "frames";
  testing::CliResult r = testing::runLbmshape(
      {"morph", (folder / "sphere.obj").string(), (folder / "box.obj").string(), out.string(), "--align", GetParam(),
       "--res", "40", "--cs", "0.3", "--frames", "3", "--steps", "60", "--format", "obj", "--no-animation", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  const double voxel = report["grid"]["voxel"];

  // B's bounding-box centre onto A's; fit also scales B to A's diagonal.
  const Bounds a = bounds(sphere), b = bounds(box);
  const double scale = fit ? a.diagonal() / b.diagonal() : 1.0;
  const glm::dvec3 translation = a.centre() - scale * b.centre();
  EXPECT_EQ(report["align"]["mode"], GetParam());
  EXPECT_NEAR(report["align"]["scale"].get<double>(), scale, 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(report["align"]["translation"][i].get<double>(), translation[i], 1e-9) << i;

  // The last frame is the box, placed so, in the sphere's coordinates.
  const Bounds last = bounds(readMesh(framePath(out, 2)));
  const glm::dvec3 expectedMin = translation + scale * b.min, expectedMax = translation + scale * b.max;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(last.min[i], expectedMin[i], 1.0 * voxel) << "axis " << i;
    EXPECT_NEAR(last.max[i], expectedMax[i], 1.0 * voxel) << "axis " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, MorphAlign, ::testing::Values("center", "fit"),
                         [](const auto& info) { return info.param; });

// A sphere into a slightly larger one converges within a few steps: with
// given steps (the paper's scheme) the log says at which step, and every
// later frame repeats that shape.
TEST(MorphConvergence, LoggedAndLaterFramesRepeatTheConvergedShape)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3, 1.0), folder / "small.obj");
  writeMesh(testing::icosphere(3, 1.1), folder / "large.obj");
  const fs::path out = folder / "frames";
  const int frames = 12;
  testing::CliResult r =
      testing::runLbmshape({"morph", (folder / "small.obj").string(), (folder / "large.obj").string(), out.string(),
                            "--align", "none", "--res", "32", "--cs", "0.5", "--frames", std::to_string(frames),
                            "--steps-per-frame", "1", "--format", "obj", "--no-animation", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  ASSERT_FALSE(report["converged_at_step"].is_null()) << r.out;
  const int converged = report["converged_at_step"];  // one step per frame: also the frame
  ASSERT_GT(converged, 0);
  ASSERT_LT(converged, frames - 1) << "converged early, with frames left to fill";
  EXPECT_EQ(report["steps"], converged) << "the lattice stopped";

  const std::regex logged("converged at step " + std::to_string(converged) + " .*frames " +
                          std::to_string(converged + 1) + " to " + std::to_string(frames - 1) + " repeat it");
  EXPECT_TRUE(std::regex_search(r.err, logged)) << r.err;
  // A warning, in the report too: the rest of the clip holds still.
  const auto& warnings = report["warnings"];
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [](const nlohmann::json& w) {
    return w.get<std::string>().rfind("converged at step ", 0) == 0;
  })) << warnings;

  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string shape = bytes(framePath(out, converged));
  ASSERT_FALSE(shape.empty());
  EXPECT_NE(shape, bytes(framePath(out, converged - 1))) << "it still moved before";
  for (int k = converged + 1; k < frames; ++k) EXPECT_EQ(bytes(framePath(out, k)), shape) << "frame " << k;
}

}  // namespace
}  // namespace lbmshape
