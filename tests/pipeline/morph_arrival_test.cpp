// A morph that arrives (no steps given): it ends on the target's own zero
// level on the grid, thin parts included; where it ends does not depend on
// --frames; its report describes every frame. And its schedule, on its own.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/pipeline/morph.hpp"
#include "lbmshape/pipeline/morph_schedule.hpp"
#include "support/morph_options.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

std::string bytes(const std::filesystem::path& p)
{
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(MorphSchedule, RunsUntilTheSourceTermHasClosedTheDistance)
{
  MorphOptions o;  // Cs 0.1, tolerance 0.1
  const int steps = MorphSchedule::stepsToArrive(20.0, o.cs, o.tolerance);
  // (1 - Cs/2)/(1 + Cs/2) a step: 20 voxels shrink below 0.1 in that many steps, not one fewer.
  const double rho = (1.0 - o.cs / 2) / (1.0 + o.cs / 2);
  EXPECT_LT(20.0 * std::pow(rho, steps), o.tolerance);
  EXPECT_GT(20.0 * std::pow(rho, steps - 1), o.tolerance);
  EXPECT_EQ(MorphSchedule::stepsToArrive(0.05, o.cs, o.tolerance), 0) << "already there";
  EXPECT_LT(MorphSchedule::stepsToArrive(20.0, 0.3, o.tolerance), steps) << "a faster Cs arrives sooner";
}

TEST(MorphSchedule, FramesSampleTheWholeMorphWhateverTheirNumber)
{
  MorphOptions few, many;
  few.frames = 5;
  const MorphSchedule a = MorphSchedule::arriving(few, 30.0);
  many.frames = a.totalSteps() + 1;  // the most that take no shorter steps
  const MorphSchedule b = MorphSchedule::arriving(many, 30.0);
  ASSERT_EQ(a.totalSteps(), b.totalSteps());
  EXPECT_EQ(b.scale(), 1.0);
  EXPECT_EQ(a.frameSteps().front(), 0);
  EXPECT_EQ(a.frameSteps().back(), a.totalSteps());
  EXPECT_EQ(b.frameSteps().back(), b.totalSteps());
  for (int s = 0; s < a.totalSteps(); ++s) EXPECT_EQ(a.gammaAt(s), b.gammaAt(s)) << "step " << s;
  // Evenly in time: frame k of 5 at a quarter of the way, and so on.
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(a.frameSteps()[size_t(k)], a.totalSteps() * k / 4.0, 0.5) << k;
}

// More frames than the morph needs steps: gamma and Cs of every step
// scaled by one factor, so that it takes a step a frame at least along the
// same way (the same ratio of gamma to Cs at the same point of it, the same
// diffusion in all) and still arrives.
TEST(MorphSchedule, MoreFramesThanStepsTakeShorterStepsOnTheSameWay)
{
  MorphOptions few, many;
  few.frames = 5;
  many.frames = 200;
  const MorphSchedule coarse = MorphSchedule::arriving(few, 30.0), fine = MorphSchedule::arriving(many, 30.0);
  ASSERT_LT(coarse.totalSteps(), many.frames - 1) << "the case needs more frames than steps";
  EXPECT_EQ(coarse.scale(), 1.0);
  EXPECT_LT(fine.scale(), 1.0);
  EXPECT_GE(fine.totalSteps(), many.frames - 1);
  EXPECT_EQ(fine.totalSteps(), many.frames - 1) << "no more steps than the frames need";
  for (size_t k = 1; k < fine.frameSteps().size(); ++k)
    EXPECT_GT(fine.frameSteps()[k], fine.frameSteps()[k - 1]) << "frame " << k << " repeats the one before";
  EXPECT_EQ(fine.frameSteps().back(), fine.totalSteps());
  for (const double along : {0.0, 0.25, 1.0}) {  // the travel, and the closing's end
    const int c = std::min(int(along * coarse.totalSteps()), coarse.totalSteps() - 1);
    const int f = std::min(int(along * fine.totalSteps()), fine.totalSteps() - 1);
    EXPECT_NEAR(fine.gammaAt(f) / fine.csAt(f), coarse.gammaAt(c) / coarse.csAt(c), 0.02 * few.gamma / few.cs) << along;
    EXPECT_NEAR(fine.gammaAt(f) / coarse.gammaAt(c), fine.scale(), 0.1 * fine.scale()) << along;
  }
  EXPECT_NEAR(fine.totalDiffusion(), coarse.totalDiffusion(), few.gamma) << "within one step's diffusion";
  double left = 30.0;  // the source term's own closing of the distance
  for (int n = 0; n < fine.totalSteps(); ++n) left *= (1.0 - fine.csAt(n) / 2.0) / (1.0 + fine.csAt(n) / 2.0);
  EXPECT_LT(left, many.tolerance);
}

// Every frame the same whole number of steps from the one before: a frame
// of two steps between frames of one moved twice as far (a stutter, the
// animator review: 50 steps over 47 intervals). Where the morph has as many
// steps as intervals or more, the factor stays within 3/4 to 3/2 (the
// nearest whole number of steps a frame); the morph still arrives.
TEST(MorphSchedule, EveryFrameIsAsManyStepsFromTheOneBefore)
{
  for (const int frames : {5, 17, 24, 48, 120, 241})
    for (const double error : {0.6, 3.0, 7.2, 30.0, 180.0}) {
      MorphOptions o;
      o.frames = frames;
      const MorphSchedule s = MorphSchedule::arriving(o, error);
      SCOPED_TRACE(std::to_string(frames) + " frames, " + std::to_string(error) + " voxels");
      const std::vector<int>& at = s.frameSteps();
      ASSERT_GT(at[1], 0);
      for (size_t k = 1; k < at.size(); ++k) ASSERT_EQ(at[k] - at[k - 1], at[1]) << "frame " << k;
      if (MorphSchedule::stepsToArrive(error, o.cs, o.tolerance) >= frames - 1) {
        EXPECT_GE(s.scale(), 0.75);
        EXPECT_LE(s.scale(), 1.5);
      } else {
        EXPECT_LE(s.scale(), 1.0) << "shorter steps, one a frame";
      }
      EXPECT_LE(s.csAt(s.totalSteps() - 1), 1.5);
      double left = error;
      for (int n = 0; n < s.totalSteps(); ++n) left *= (1.0 - s.csAt(n) / 2.0) / (1.0 + s.csAt(n) / 2.0);
      EXPECT_LT(left, o.tolerance);
    }
}

TEST(MorphSchedule, GammaAndCsHoldThenCloseOnTheArrivalsValues)
{
  MorphOptions o;
  const MorphSchedule s = MorphSchedule::arriving(o, 30.0);
  ASSERT_TRUE(s.annealed());
  EXPECT_EQ(s.annealFrom(), s.totalSteps() / 2);
  const double scale = s.scale();  // the frames' even steps' (MorphSchedule.EveryFrameIsAsManyStepsFromTheOneBefore)
  for (int k = 0; k < s.annealFrom(); ++k) {
    EXPECT_DOUBLE_EQ(s.gammaAt(k), o.gamma * scale);
    EXPECT_DOUBLE_EQ(s.csAt(k), o.cs * scale);
  }
  for (int k = s.annealFrom() + 1; k < s.totalSteps(); ++k) {
    EXPECT_LE(s.gammaAt(k), s.gammaAt(k - 1)) << k;
    EXPECT_GE(s.csAt(k), s.csAt(k - 1)) << k;
  }
  EXPECT_DOUBLE_EQ(s.gammaAt(s.totalSteps() - 1), arrivalGamma * scale);
  EXPECT_DOUBLE_EQ(s.csAt(s.totalSteps() - 1), arrivalCs * scale);
  EXPECT_LT(s.totalDiffusion(), o.gamma * scale * s.totalSteps());
  // Batches never cross a change of gamma.
  for (int k = 0; k < s.totalSteps(); ++k)
    for (int j = k; j < s.sameStepsUntil(k); ++j) {
      EXPECT_EQ(s.gammaAt(j), s.gammaAt(k)) << k << " " << j;
      EXPECT_EQ(s.csAt(j), s.csAt(k)) << k << " " << j;
    }
  // Values already past the arrival's are kept.
  o.gamma = arrivalGamma / 2;
  o.cs = arrivalCs;
  EXPECT_FALSE(MorphSchedule::arriving(o, 30.0).annealed());
}

class MorphArrival : public ::testing::Test {
protected:
  ComputeDevice device{"", true};  // Vulkan, with the validation layer
  testing::ScratchFolder folder;

  // The tests' morph: on a 48-cell grid, unaligned, frames as OBJ files, no animation.
  static MorphOptions options(int frames, bool band = false)
  {
    MorphOptions o = testing::objFramesMorph(48, frames);
    o.band = band;
    return o;
  }

  nlohmann::json morph(const std::string& target, const std::string& out, int frames, bool band = false)
  {
    return morphFiles(folder / "sphere.obj", folder / target, folder / out, options(frames, band), device);
  }
};

// A torus whose ring is under three voxels thick: the paper's constant gamma
// leaves it eroded (its steady state is gamma/Cs times the curvature off,
// about half a voxel here); the arriving morph ends on it.
TEST_F(MorphArrival, EndsOnTheTargetsZeroLevelThinPartsIncluded)
{
  writeMesh(testing::icosphere(4, 1.0), folder / "sphere.obj");
  writeMesh(testing::torusMesh(1.0, 0.07, 128, 24), folder / "ring.obj");
  for (const bool band : {false, true}) {
    const nlohmann::json report = morph("ring.obj", band ? "band" : "grid", 8, band);
    SCOPED_TRACE(band ? "band" : "grid");
    const double voxel = report["grid"]["voxel"];
    ASSERT_LT(2 * 0.07 / voxel, 3.0) << "the ring is thin";
    EXPECT_TRUE(report["converged"]);
    EXPECT_LT(report["final"]["mean_distance_to_target_level_voxels"].get<double>(), 0.05);
    EXPECT_LT(report["final"]["hausdorff_to_target_level_voxels"].get<double>(), 1.0);
    EXPECT_EQ(report["final"]["genus"], 1);
  }

  // The paper's scheme, for as many steps, stays further off.
  MorphOptions o = testing::objFramesMorph(48, 8);
  o.steps = morph("ring.obj", "again", 8)["steps"].get<int>();
  const nlohmann::json paper = morphFiles(folder / "sphere.obj", folder / "ring.obj", folder / "paper", o, device);
  EXPECT_GT(paper["final"]["mean_distance_to_target_level_voxels"].get<double>(), 0.1);
}

// A shape into itself is there before any step: a step of the closing's Cs
// of 1 would move the field by a quarter of a voxel where the target's
// distance field has kinks (the cube's edges), off the target it started on.
TEST_F(MorphArrival, AShapeIntoItselfTakesNoStepAndEndsOnItsOwnLevel)
{
  writeMesh(testing::icosphere(3, 1.0), folder / "sphere.obj");
  writeMesh(testing::box({-0.7, -0.5, -0.6}, {0.8, 0.6, 0.5}), folder / "box.obj");
  for (const bool band : {false, true}) {
    SCOPED_TRACE(band ? "band" : "grid");
    MorphOptions o;
    o.grid.resolution = 40;
    o.format = "obj";
    o.frames = 3;
    o.band = band;
    o.animation = false;
    const nlohmann::json report =
        morphFiles(folder / "box.obj", folder / "box.obj", folder / (band ? "band" : "grid"), o, device);
    EXPECT_EQ(report["steps"], 0);
    EXPECT_EQ(report["frame_steps"], nlohmann::json({0, 0, 0}));
    EXPECT_TRUE(report["converged"]);
    EXPECT_TRUE(report["schedule"]["final_gamma"].is_null());
    EXPECT_LT(report["final"]["hausdorff_to_target_level_voxels"].get<double>(), 0.01);
    EXPECT_EQ(bytes(folder / (band ? "band" : "grid") / "frame_0000.obj"),
              bytes(folder / (band ? "band" : "grid") / "frame_0002.obj"));
  }
}

TEST_F(MorphArrival, FramesChangeHowManyPicturesNeverWhereItEnds)
{
  writeMesh(testing::icosphere(3, 1.0), folder / "sphere.obj");
  writeMesh(testing::torusMesh(1.0, 0.35, 64, 32), folder / "torus.obj");
  const nlohmann::json few = morph("torus.obj", "few", 5), many = morph("torus.obj", "many", 17);
  ASSERT_EQ(few["steps"], many["steps"]);
  // 5 frames are every fourth of 17: the same steps, the same files.
  for (int k = 0; k < 5; ++k) {
    char a[32], b[32];
    std::snprintf(a, sizeof a, "frame_%04d.obj", k);
    std::snprintf(b, sizeof b, "frame_%04d.obj", 4 * k);
    EXPECT_EQ(few["frame_steps"][k], many["frame_steps"][4 * k]) << k;
    EXPECT_EQ(bytes(folder / "few" / a), bytes(folder / "many" / b)) << k;
  }
}

// A morph that arrives in fewer steps than a clip has frames takes shorter
// ones: every frame a shape of its own (they repeated: the clip played in
// jerks), on the way the frames of a short clip show, to the same end.
TEST_F(MorphArrival, MoreFramesThanStepsGiveEachFrameItsOwnShapeOnTheSameWay)
{
  writeMesh(testing::icosphere(3, 1.0), folder / "sphere.obj");
  writeMesh(testing::torusMesh(1.0, 0.35, 64, 32), folder / "torus.obj");
  const nlohmann::json coarse = morph("torus.obj", "coarse", 5);
  const int between = coarse["steps"].get<int>() / 4 + 1;  // fine frames per coarse one
  const int frames = 4 * between + 1;
  const nlohmann::json fine = morph("torus.obj", "fine", frames);
  ASSERT_GT(frames - 1, coarse["steps"].get<int>()) << "the case needs more frames than steps";
  EXPECT_LT(fine["schedule"]["scale"].get<double>(), 1.0);
  ASSERT_EQ(fine["steps"], frames - 1) << "a step a frame: frame k is step k";
  const auto frameFile = [&](const char* run, int k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.obj", k);
    return folder / run / name;
  };
  for (int k = 1; k < frames; ++k) {
    EXPECT_GT(fine["frame_steps"][size_t(k)].get<int>(), fine["frame_steps"][size_t(k - 1)].get<int>()) << k;
    EXPECT_NE(bytes(frameFile("fine", k)), bytes(frameFile("fine", k - 1))) << "frame " << k << " repeats";
  }
  EXPECT_TRUE(fine["converged"]);
  EXPECT_LT(fine["final"]["mean_distance_to_target_level_voxels"].get<double>(), 0.05);
  EXPECT_LT(fine["final"]["hausdorff_to_target_level_voxels"].get<double>(), 1.0);
  // Halfway, the two runs' frames at the same time (a step of either lasts
  // its `scale`) lie on one another; a quarter of the way further on, the
  // shape is elsewhere.
  const double voxel = coarse["grid"]["voxel"];
  const int halfway = coarse["frame_steps"][2];
  const int sameTime =
      int(std::lround(halfway * coarse["schedule"]["scale"].get<double>() / fine["schedule"]["scale"].get<double>()));
  const TriangleMesh half = readMesh(frameFile("coarse", 2));
  const double same = compareSurfaces(half, readMesh(frameFile("fine", sameTime))).mean / voxel;
  const double later = compareSurfaces(half, readMesh(frameFile("fine", sameTime + between))).mean / voxel;
  EXPECT_LT(same, 0.1);
  EXPECT_GT(later, 4 * same);
}

// Given steps that arrive before the last frame: the lattice stops there,
// and frame_steps says the step each frame was made at, as per_frame does,
// not the schedule's plan; frame 0 had no step leading to it.
TEST_F(MorphArrival, FrameStepsSayWhereAMorphThatStoppedEarlyMadeItsFrames)
{
  writeMesh(testing::icosphere(3, 1.0), folder / "sphere.obj");
  writeMesh(testing::scaled(testing::icosphere(3, 1.0), 0.8), folder / "smaller.obj");
  MorphOptions o = options(6);
  o.grid.resolution = 32;
  o.stepsPerFrame = 40;
  const nlohmann::json report = morphFiles(folder / "sphere.obj", folder / "smaller.obj", folder / "early", o, device);
  ASSERT_FALSE(report["converged_at_step"].is_null()) << "the case needs a morph that arrives early";
  ASSERT_LT(report["steps"].get<int>(), 40 * (o.frames - 1));
  for (int k = 0; k < o.frames; ++k)
    EXPECT_EQ(report["frame_steps"][size_t(k)], report["per_frame"][size_t(k)]["step"]) << k;
  EXPECT_EQ(report["frame_steps"][size_t(o.frames - 1)], report["steps"]);
  EXPECT_TRUE(report["per_frame"][0]["gamma"].is_null());
  EXPECT_TRUE(report["per_frame"][0]["cs"].is_null());
  EXPECT_EQ(report["per_frame"][1]["gamma"], o.gamma);
}

TEST_F(MorphArrival, ReportsEveryFrame)
{
  writeMesh(testing::icosphere(3, 1.0), folder / "sphere.obj");
  writeMesh(testing::torusMesh(1.0, 0.35, 64, 32), folder / "torus.obj");
  const int frames = 9;
  const nlohmann::json report = morph("torus.obj", "frames", frames);
  const nlohmann::json& perFrame = report["per_frame"];
  ASSERT_EQ(perFrame.size(), size_t(frames));
  for (int k = 0; k < frames; ++k) {
    const nlohmann::json& f = perFrame[size_t(k)];
    SCOPED_TRACE("frame " + std::to_string(k));
    EXPECT_EQ(f["frame"], k);
    EXPECT_EQ(f["step"], report["frame_steps"][size_t(k)]);
    EXPECT_GT(f["volume"].get<double>(), 0.0);
    EXPECT_EQ(f["components"], 1);
    EXPECT_GE(f["mean_distance_to_target_voxels"].get<double>(), 0.0);
    EXPECT_GE(f["max_distance_to_target_voxels"].get<double>(), f["mean_distance_to_target_voxels"].get<double>());
    if (k > 0) {
      EXPECT_LT(f["mean_distance_to_target_voxels"].get<double>(),
                perFrame[size_t(k - 1)]["mean_distance_to_target_voxels"].get<double>() + 0.01);
    }
  }
  EXPECT_EQ(perFrame[0]["genus"], 0) << "the sphere";
  EXPECT_EQ(perFrame[frames - 1]["genus"], 1) << "the torus";
  EXPECT_FALSE(perFrame[0]["converged"]);
  EXPECT_TRUE(perFrame[frames - 1]["converged"]);
  EXPECT_LT(perFrame[frames - 1]["mean_distance_to_target_voxels"].get<double>(), 0.05);
}

}  // namespace
}  // namespace lbmshape
