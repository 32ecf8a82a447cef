// lbmshape morph on shapes made in code: a sphere becomes a torus (genus 0 to
// 1), frame by frame closer to it; frame 0 is the source; the frame files and
// the animation are what the options say.
#include <fstream>
#include <iterator>

#include <algorithm>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/pipeline/morph.hpp"
#include "lbmshape/pipeline/morph_schedule.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

class Morph : public ::testing::Test {
protected:
  ComputeDevice device{"", true};  // Vulkan, with the validation layer
  testing::ScratchFolder folder;
  TriangleMesh sphere = testing::icosphere(4, 1.0);
  TriangleMesh torus = testing::torusMesh(1.0, 0.4, 96, 48);

  void SetUp() override
  {
    writeMesh(sphere, folder / "sphere.obj");
    writeMesh(torus, folder / "torus.obj");
  }
  nlohmann::json morph(const MorphOptions& options)
  {
    return morphFiles(folder / "sphere.obj", folder / "torus.obj", folder / "frames", options, device);
  }
  static MorphOptions sphereToTorus()
  {
    MorphOptions o;
    o.grid.resolution = 64;
    o.align = Alignment::None;
    o.format = "obj";
    return o;
  }
  TriangleMesh frame(int k)
  {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.obj", k);
    return readMesh(folder / "frames" / name);
  }
};

TEST_F(Morph, SphereBecomesTorusFrameByFrame)
{
  const MorphOptions options = sphereToTorus();
  const nlohmann::json report = morph(options);
  const double voxel = report["grid"]["voxel"];
  ASSERT_EQ(report["frames"], 48);

  const TriangleMesh last = frame(47);
  const MeshTopology t = analyzeTopology(last);
  EXPECT_TRUE(t.closedManifold);
  EXPECT_EQ(t.genus, 1);
  const SurfaceComparison final = compareSurfaces(last, torus);
  EXPECT_LT(final.hausdorff, 1.0 * voxel);

  // The mean distance to the torus falls at every frame that is a step
  // further on (until it has settled to within the samples' precision, a
  // hundredth of a voxel); a morph shorter than its frames shows some steps
  // twice.
  double previous = 1e30;
  for (int k = 0; k < 48; ++k) {
    const double mean = compareSurfaces(frame(k), torus, ComparisonOptions{20000, 0.0, false}).mean / voxel;
    EXPECT_LT(mean, previous + 0.01) << "frame " << k;
    if (previous > 0.05 && (k == 0 || report["frame_steps"][k] != report["frame_steps"][k - 1])) {
      EXPECT_LT(mean, previous) << "frame " << k;
    }
    previous = mean;
  }
}

TEST_F(Morph, FrameZeroIsTheSource)
{
  morph(sphereToTorus());
  const nlohmann::json report = morph([] {
    MorphOptions o = sphereToTorus();
    o.force = true;
    return o;
  }());
  const double voxel = report["grid"]["voxel"];
  EXPECT_LT(compareSurfaces(frame(0), sphere).mean, 0.5 * voxel);
}

TEST_F(Morph, GivenStepsAreSpreadOverTheFrames)
{
  MorphOptions o;
  o.frames = 5;
  EXPECT_EQ(MorphSchedule::fixed(o).frameSteps(), (std::vector<int>{0, 1, 2, 3, 4}));
  o.stepsPerFrame = 3;
  EXPECT_EQ(MorphSchedule::fixed(o).frameSteps(), (std::vector<int>{0, 3, 6, 9, 12}));
  o.stepsPerFrame.reset();
  o.steps = 10;
  const MorphSchedule given = MorphSchedule::fixed(o);
  EXPECT_EQ(given.frameSteps(), (std::vector<int>{0, 3, 5, 8, 10}));
  EXPECT_FALSE(given.annealed());
  for (int s = 0; s < 10; ++s) EXPECT_EQ(given.gammaAt(s), o.gamma) << "the paper's scheme keeps gamma";
}

// The lattice steps of a frame run in batches with a Ctrl-C check between
// them; whatever the batches, the frames are the same bytes.
TEST_F(Morph, FramesDoNotDependOnTheBatchesOfSteps)
{
  auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  MorphOptions o = sphereToTorus();
  o.grid.resolution = 32;
  o.frames = 4;
  o.stepsPerFrame = 7;
  o.animation = false;
  for (const auto& [batch, out] :
       {std::pair<std::optional<int>, const char*>{1, "one"}, {3, "three"}, {std::nullopt, "adaptive"}}) {
    o.stepsPerBatch = batch;
    morphFiles(folder / "sphere.obj", folder / "torus.obj", folder / out, o, device);
  }
  for (int k = 0; k < o.frames; ++k) {
    const std::string name = "frame_000" + std::to_string(k) + ".obj";
    const std::string one = bytes(folder / "one" / name);
    EXPECT_FALSE(one.empty()) << name;
    EXPECT_EQ(one, bytes(folder / "three" / name)) << name;
    EXPECT_EQ(one, bytes(folder / "adaptive" / name)) << name;
  }
}

TEST_F(Morph, ConvergedMorphRepeatsItsLastShape)
{
  // Morphing the torus into itself converges at once; with given steps the
  // lattice then stops.
  MorphOptions o = sphereToTorus();
  o.frames = 6;
  o.stepsPerFrame = 1;
  const nlohmann::json report = morphFiles(folder / "torus.obj", folder / "torus.obj", folder / "frames", o, device);
  ASSERT_FALSE(report["converged_at_step"].is_null());
  EXPECT_EQ(report["converged_at_step"], 1);
  EXPECT_EQ(report["steps"], 1);
  EXPECT_EQ(frame(5).positions, frame(1).positions);
}

TEST_F(Morph, RefusesANonEmptyFolderUnlessForced)
{
  MorphOptions o = sphereToTorus();
  o.frames = 3;
  std::filesystem::create_directories(folder / "frames");
  writeMesh(sphere, folder / "frames" / "mine.obj");
  EXPECT_THROW(morph(o), OutputError);
  o.force = true;
  EXPECT_NO_THROW(morph(o));
  EXPECT_TRUE(std::filesystem::exists(folder / "frames" / "mine.obj")) << "--force only replaces frames";
}

// A forced morph over a longer one replaces all of its files, and leaves
// nothing of its own making behind (the hidden folder it made them in).
TEST_F(Morph, AForcedMorphReplacesAnEarlierLongerOne)
{
  MorphOptions o = sphereToTorus();
  o.frames = 4;
  morph(o);
  o.frames = 2;
  o.force = true;
  morph(o);
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder / "frames"))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frame_0000.obj", "frame_0001.obj", "morph.glb"}));
}

}  // namespace
}  // namespace lbmshape
