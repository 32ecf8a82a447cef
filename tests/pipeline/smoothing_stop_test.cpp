// --steps auto (pipeline/smoothing_stop.hpp): the surface's speed, the rule
// that reads the end of the noise off it, and a denoise that takes more steps
// the noisier its input.
#include <gtest/gtest.h>

#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/pipeline/smoothing_stop.hpp"
#include "lbmshape/sdf/grid_frame.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

using namespace smoothing_stop;

TEST(SurfaceSpeed, IsTheSpreadOfTheChangeOverTheLastFieldsSurfaceCells)
{
  // Cells 0 and 2 are on the surface (|X| < 1) before; cell 1 is not, and
  // its large change does not count. Changes -0.1 and -0.3: mean -0.2,
  // standard deviation 0.1.
  SurfaceSpeed speed({0.5f, 3.0f, -0.2f});
  EXPECT_NEAR(speed.advance({0.4f, 1.0f, -0.5f}), 0.1, 1e-7);
  // The surface is now the new field's: cells 0 and 2 again (1.0 is not
  // below 1 voxel); changes 0 and +0.4.
  EXPECT_NEAR(speed.advance({0.4f, 1.0f, -0.1f}), 0.2, 1e-7);
}

TEST(SurfaceSpeed, LevelsOffOnlyAfterTheFewestSteps)
{
  // Speeds falling by half a step, then by 10 %: the noise is gone at step 4,
  // so step 3's field is kept.
  const double speeds[] = {0.0, 0.16, 0.08, 0.04, 0.036, 0.034};
  int kept = -1;
  for (int n = 2; n <= 5 && kept < 0; ++n)
    if (levelledOff(n, speeds[n - 1], speeds[n])) kept = n - 1;
  EXPECT_EQ(kept, 3);
  // Level from the start: the fewest steps.
  EXPECT_FALSE(levelledOff(2, 0.03, 0.03));
  EXPECT_TRUE(levelledOff(3, 0.03, 0.03));
  // Still falling steeply, but the surface hardly moves: nothing is left.
  EXPECT_FALSE(levelledOff(3, 0.03, 0.02));
  EXPECT_TRUE(levelledOff(3, 0.004, 0.002));
  EXPECT_FALSE(levelledOff(2, 0.004, 0.002)) << "never before the fewest steps";
}

class AutoSteps : public ::testing::Test {
protected:
  ComputeDevice device{"", true};
  testing::ScratchFolder folder;

  nlohmann::json denoise(const TriangleMesh& mesh, std::optional<int> steps = {}, bool dense = false)
  {
    writeMesh(mesh, folder.path() / "in.obj");
    DenoiseOptions options;
    options.grid.resolution = 64;
    options.steps = steps;
    options.dense = dense;
    options.twicing = false;  // the rule's own steps (twiced, the report gives S's: twicing_test.cpp)
    return denoiseFile(folder.path() / "in.obj", folder.path() / "out.obj", options, device).report;
  }
};

TEST_F(AutoSteps, TheNoisierTheInputTheMoreSteps)
{
  const TriangleMesh torus = testing::torusMesh(1.0, 0.4, 192, 96);
  // Noise in voxels of the grid at --res 64 (as `lbmshape noise --res 64`).
  const double voxel = frameWithResolution(bounds(torus), 64, 4.0).voxel, edge = meanEdgeLength(torus);
  int previous = 0;
  for (double sigma : {0.0, 0.5, 1.0}) {
    const nlohmann::json r = denoise(sigma > 0 ? addNormalNoise(torus, sigma * voxel / edge, 3) : torus);
    EXPECT_EQ(r["steps_chosen"], "auto");
    const int steps = r["steps"];
    EXPECT_GE(steps, fewestSteps);
    EXPECT_LE(steps, mostSteps);
    if (sigma == 0.0) {
      EXPECT_LE(steps, fewestSteps + 1) << "a clean torus needs few";
    }
    if (sigma == 1.0) {
      EXPECT_GT(steps, fewestSteps + 2) << "sigma 1 voxel";
    }
    EXPECT_GE(steps, previous) << "sigma " << sigma;
    previous = steps;
  }
}

// A thin tube (3.4 voxels thick) shrinks by gamma kappa a step everywhere
// while its noise goes; that uniform move is what keeping the volume gives
// back, and the speed leaves it out, so the rule smooths until the noise is
// gone instead of stopping at the tube's own shrinking. With the mean
// |change| as the speed (until 2026-11-27; shown by putting it back, on the
// device and the host) the rule kept the fewest steps here and this test
// failed; with the spread it keeps more, with less normal error.
TEST_F(AutoSteps, ANoisyThinTubeIsSmoothedUntilItsNoiseIsGone)
{
  const TriangleMesh tube = testing::torusMesh(1.0, 0.12, 256, 48);
  const double voxel = frameWithResolution(bounds(tube), 64, 4.0).voxel, edge = meanEdgeLength(tube);
  const TriangleMesh noisy = addNormalNoise(tube, 1.0 * voxel / edge, 3);
  DenoiseOptions options;
  options.grid.resolution = 64;
  options.twicing = false;  // the rule's own steps
  const DenoiseResult chosen = denoiseMesh(noisy, "thin tube", options, device);
  const int steps = chosen.report["steps"];
  EXPECT_GE(steps, fewestSteps + 2);
  options.steps = fewestSteps;
  const DenoiseResult fewest = denoiseMesh(noisy, "thin tube", options, device);
  const SurfaceComparison c = compareSurfaces(tube, chosen.mesh, ComparisonOptions{20000});
  const SurfaceComparison f = compareSurfaces(tube, fewest.mesh, ComparisonOptions{20000});
  EXPECT_LT(c.meanNormalAngle, 0.85 * f.meanNormalAngle) << steps << " steps against " << fewestSteps;
  EXPECT_LE(c.bToA.mean, 1.05 * f.bToA.mean);
}

// The band reads its fields one step late from its two copies, the grid
// each step as it is taken: the same rule on the same readings. Their first
// readings agree to float rounding (a band that read a step early or late
// would be off by a factor of two or more); later ones differ by up to 19 %
// on this torus, as the two lattices' starts and edge-finding copies differ
// a little (`StartUpTransient`) and the speed, the change less its mean,
// is what is left of a larger change; so a ratio near the rule's threshold
// can take one a step further than the other, never more.
TEST_F(AutoSteps, TheBandAndTheGridReadTheSameSpeeds)
{
  const TriangleMesh torus = testing::torusMesh(1.0, 0.4, 192, 96);
  const double voxel = frameWithResolution(bounds(torus), 64, 4.0).voxel, edge = meanEdgeLength(torus);
  for (double sigma : {0.0, 0.7}) {
    const TriangleMesh input = sigma > 0 ? addNormalNoise(torus, sigma * voxel / edge, 5) : torus;
    const nlohmann::json band = denoise(input), grid = denoise(input, {}, true);
    EXPECT_EQ(band["lattice"]["kind"], "band");
    EXPECT_EQ(grid["lattice"]["kind"], "grid");
    const auto bandSpeeds = band["surface_speeds"].get<std::vector<double>>();
    const auto gridSpeeds = grid["surface_speeds"].get<std::vector<double>>();
    ASSERT_FALSE(bandSpeeds.empty());
    ASSERT_FALSE(gridSpeeds.empty());
    EXPECT_NEAR(bandSpeeds[0], gridSpeeds[0], 1e-4 * gridSpeeds[0]) << "sigma " << sigma;
    for (size_t k = 1; k < std::min(bandSpeeds.size(), gridSpeeds.size()); ++k)
      EXPECT_NEAR(bandSpeeds[k], gridSpeeds[k], 0.25 * gridSpeeds[k]) << "sigma " << sigma << ", reading " << k;
    EXPECT_NEAR(band["steps"].get<int>(), grid["steps"].get<int>(), 1) << "sigma " << sigma;
    // One reading a step the rule looked at: the kept step and the one
    // that levelled off (none beyond the most steps).
    const int steps = band["steps"].get<int>();
    EXPECT_EQ(bandSpeeds.size(), size_t(steps < mostSteps ? steps + 1 : steps)) << "sigma " << sigma;
  }
}

TEST_F(AutoSteps, GivenStepsAreTaken)
{
  const nlohmann::json r = denoise(testing::torusMesh(1.0, 0.4, 64, 32), 5);
  EXPECT_EQ(r["steps"], 5);
  EXPECT_EQ(r["steps_chosen"], "given");
}

}  // namespace
}  // namespace lbmshape
