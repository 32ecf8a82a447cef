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
#include "lbmshape/pipeline/twicing.hpp"
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
  // Speeds falling by half a step, then by 10 %: the noise is gone at step 5,
  // so step 4's field is kept.
  const double speeds[] = {0.0, 0.32, 0.16, 0.08, 0.04, 0.036, 0.034};
  int kept = -1;
  for (int n = 2; n <= 6 && kept < 0; ++n)
    if (levelledOff(n, speeds[n - 1], speeds[n])) kept = n - 1;
  EXPECT_EQ(kept, 4);
  // Level from the start: the fewest steps.
  EXPECT_FALSE(levelledOff(fewestSteps, 0.03, 0.03));
  EXPECT_TRUE(levelledOff(fewestSteps + 1, 0.03, 0.03));
  // Still falling steeply, but the surface hardly moves: nothing is left.
  EXPECT_FALSE(levelledOff(fewestSteps + 1, 0.03, 0.02));
  EXPECT_TRUE(levelledOff(fewestSteps + 1, 0.004, 0.002));
  EXPECT_FALSE(levelledOff(fewestSteps, 0.004, 0.002)) << "never before the fewest steps";
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

  // `clean` with Gaussian noise of `voxels` along its normals, in voxels of
  // the grid at --res 64 (as `lbmshape noise --res 64`).
  static TriangleMesh withNoise(const TriangleMesh& clean, double voxels)
  {
    const double voxel = frameWithResolution(bounds(clean), 64, 4.0).voxel;
    return addNormalNoise(clean, voxels * voxel / meanEdgeLength(clean), 3);
  }
  static DenoiseOptions defaultsAt64()
  {
    DenoiseOptions options;
    options.grid.resolution = 64;
    return options;
  }

  // `noisy` denoised with `options` and with the fewest steps, each result
  // compared with `clean`.
  struct AgainstTheFewest {
    nlohmann::json report;
    TriangleMesh mesh;
    SurfaceComparison chosen, fewest;
  };
  AgainstTheFewest againstTheFewest(const TriangleMesh& clean, const TriangleMesh& noisy, DenoiseOptions options)
  {
    DenoiseResult chosen = denoiseMesh(noisy, "noisy", options, device);
    options.steps = smoothing_stop::fewestSteps;
    const DenoiseResult fewest = denoiseMesh(noisy, "noisy", options, device);
    const SurfaceComparison c = compareSurfaces(clean, chosen.mesh, ComparisonOptions{20000});
    const SurfaceComparison f = compareSurfaces(clean, fewest.mesh, ComparisonOptions{20000});
    return {std::move(chosen.report), std::move(chosen.mesh), c, f};
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
  const AgainstTheFewest r = againstTheFewest(tube, noisy, options);
  const int steps = r.report["steps"];
  EXPECT_GE(steps, fewestSteps + 2);
  EXPECT_LT(r.chosen.meanNormalAngle, 0.85 * r.fewest.meanNormalAngle) << steps << " steps against " << fewestSteps;
  EXPECT_LE(r.chosen.bToA.mean, 1.05 * r.fewest.bToA.mean);
}

// Where the noise's amplitude sets the steps (`options` choosing them),
// the result is the field of those steps, plain: as --steps N --no-twicing
// gives it, on the band (which reads one step late) and on the grid alike.
void expectTheFieldOfTheNoisesSteps(const TriangleMesh& noisy, DenoiseOptions options, const ComputeDevice& device)
{
  for (bool dense : {false, true}) {
    const char* lattice = dense ? "grid" : "band";
    options.dense = dense;
    options.steps.reset();
    options.twicing.reset();
    const DenoiseResult automatic = denoiseMesh(noisy, "noisy", options, device);
    const int steps = automatic.report["steps"];
    EXPECT_EQ(steps, automatic.report["noise_steps"].get<int>()) << lattice;
    EXPECT_FALSE(automatic.report["twicing"].get<bool>()) << lattice;
    options.steps = steps;
    options.twicing = false;
    const DenoiseResult given = denoiseMesh(noisy, "noisy", options, device);
    const double voxel = given.report["grid"]["voxel"];
    EXPECT_LT(compareSurfaces(automatic.mesh, given.mesh, ComparisonOptions{20000}).mean, 1e-3 * voxel) << lattice;
  }
}

// An icosphere of 320 triangles, each about 8 voxels long at --res 64,
// with noise of 1.5 voxels along its normals: each triangle is tilted
// whole, the noise fades as slowly as the shape, and the surface's speed
// levels off at the fewest steps. Its amplitude, read off the mesh, asks
// for more; smoothed so, the result is nearer the clean sphere on both
// measures than the fewest steps leave it. Without the noise's steps it
// keeps the fewest and this test fails.
TEST_F(AutoSteps, ALowPolyInputIsSmoothedAsItsNoisesAmplitudeAsks)
{
  const TriangleMesh sphere = testing::icosphere(2);
  const TriangleMesh noisy = withNoise(sphere, 1.5);
  DenoiseOptions options = defaultsAt64();
  const AgainstTheFewest r = againstTheFewest(sphere, noisy, options);
  EXPECT_NEAR(r.report["noise_amplitude_voxels"].get<double>(), 1.5, 0.3);
  const int steps = r.report["steps"];
  EXPECT_GT(steps, int(r.report["surface_speeds"].size()) - 1) << "more than the speed's own";
  EXPECT_LT(r.chosen.meanNormalAngle, 0.95 * r.fewest.meanNormalAngle) << steps << " steps against " << fewestSteps;
  EXPECT_LT(r.chosen.bToA.mean, 0.98 * r.fewest.bToA.mean);
  expectTheFieldOfTheNoisesSteps(noisy, options, device);
}

// With 1.1 voxels of noise the same sphere's amplitude asks for the step at
// which its speed levelled off, one more than the speed keeps: the field
// of that step, which the lattice holds, not the one before it.
TEST_F(AutoSteps, TheNoisesStepsMayEndWhereTheSpeedLevelledOff)
{
  const TriangleMesh sphere = testing::icosphere(2);
  const TriangleMesh noisy = withNoise(sphere, 1.1);
  DenoiseOptions options = defaultsAt64();
  const DenoiseResult chosen = denoiseMesh(noisy, "noisy", options, device);
  EXPECT_EQ(chosen.report["steps"].get<int>(), int(chosen.report["surface_speeds"].size()));
  expectTheFieldOfTheNoisesSteps(noisy, options, device);
}

// A torus of 576 triangles with 1.5 voxels of noise: its speed levels off
// late enough for twicing (4 steps kept), its amplitude asks for more, and
// the smoothing runs them plain, nearer the clean torus on both measures
// than the speed's own steps plain; twiced, it would give the slow noise
// back (and did, before the amplitude's steps came first).
TEST_F(AutoSteps, TheNoisesStepsAreNotTwiced)
{
  const TriangleMesh torus = testing::torusMesh(1.0, 0.4, 24, 12);
  const TriangleMesh noisy = withNoise(torus, 1.5);
  DenoiseOptions options = defaultsAt64();
  const DenoiseResult chosen = denoiseMesh(noisy, "noisy", options, device);
  const int bySpeed = int(chosen.report["surface_speeds"].size()) - 1;
  ASSERT_GE(bySpeed, twicingFromSteps) << "the speed alone would twice";
  EXPECT_GT(chosen.report["steps"].get<int>(), bySpeed);
  expectTheFieldOfTheNoisesSteps(noisy, options, device);
  options.steps = bySpeed;
  options.twicing = false;
  const DenoiseResult speedsOwn = denoiseMesh(noisy, "noisy", options, device);
  const SurfaceComparison c = compareSurfaces(torus, chosen.mesh, ComparisonOptions{20000});
  const SurfaceComparison s = compareSurfaces(torus, speedsOwn.mesh, ComparisonOptions{20000});
  EXPECT_LT(c.meanNormalAngle, s.meanNormalAngle);
  EXPECT_LT(c.bToA.mean, s.bToA.mean);
}

// The steps of a noise amplitude (voxels) at gamma = 0.2: the spread of n
// steps is 0.33, 0.73, 1.13, 1.53 voxels^2 for n = 1 to 4, which 1.1 times
// the amplitude must reach; never more than mostSteps.
TEST(NoiseSteps, AreTheFewestWhoseSpreadReachesTheAmplitudeWithItsMargin)
{
  EXPECT_EQ(fewestStepsForNoise(0.0, 0.2), 1);
  EXPECT_EQ(fewestStepsForNoise(0.96, 0.2), 3);  // 1.056 against sqrt(1.13) = 1.062
  EXPECT_EQ(fewestStepsForNoise(1.03, 0.2), 4);  // 1.133
  EXPECT_EQ(fewestStepsForNoise(100.0, 0.2), mostSteps);
  EXPECT_LT(fewestStepsForNoise(1.03, 0.5), 4) << "a larger gamma spreads further a step";
}

// A clean mesh reads as almost no noise, and its steps are the speed's.
TEST_F(AutoSteps, ACleanMeshsNoiseAsksForNoMoreSteps)
{
  const nlohmann::json r = denoise(testing::torusMesh(1.0, 0.4, 192, 96));
  EXPECT_LT(r["noise_amplitude_voxels"].get<double>(), 0.05);
  EXPECT_EQ(r["noise_steps"], 1);
  EXPECT_EQ(r["steps"], fewestSteps);
  const nlohmann::json given = denoise(testing::torusMesh(1.0, 0.4, 192, 96), 2);
  EXPECT_TRUE(given["noise_amplitude_voxels"].is_null()) << "not read with --steps";
  EXPECT_TRUE(given["noise_steps"].is_null());
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
