// What `bench` times: the runs after the warm-up, and how many steps each.
#include <chrono>

#include <gtest/gtest.h>

#include "lbmshape/bench/lattice_bench.hpp"

namespace lbmshape {
namespace {

// A solver whose every step takes at least `stepMs`, as a large grid on the
// CPU reference does.
class SlowSteps final : public SteppingSolver {
public:
  explicit SlowSteps(double stepMs) : stepMs_(stepMs) {}
  std::string backendName() const override { return "slow"; }
  void step(int count) override
  {
    for (int i = 0; i < count; ++i) {
      const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double, std::milli>(stepMs_);
      while (std::chrono::steady_clock::now() < until) {}
      ++taken_;
    }
  }
  int stepsTaken() const override { return taken_; }

private:
  double stepMs_;
  int taken_ = 0;
};

BenchSettings quick()
{
  BenchSettings settings;
  settings.steps = 100;
  settings.runs = 2;
  settings.warmupMs = 6.0;
  return settings;
}

TEST(StepTiming, RunsTakeTheStepsAsked)
{
  SlowSteps solver(0.05);
  const StepTiming timing = timeSteps(solver, quick(), 1000.0);
  EXPECT_EQ(timing.stepsPerRun, 100);
  EXPECT_EQ(solver.stepsTaken(), 1 + timing.warmupSteps + 2 * 100);
}

// The reference's runs are cut to its own pace: at 2 ms or more a step, runs
// of at most 0.4 s hold at most 200 steps, whatever --steps asked.
TEST(StepTiming, TheReferencesRunsAreCutToItsPace)
{
  BenchSettings settings = referenceSettings(quick());
  settings.steps = 1000;
  SlowSteps solver(2.0);
  const StepTiming timing = timeSteps(solver, settings, 1000.0);
  EXPECT_GE(timing.stepsPerRun, 1);
  EXPECT_LE(timing.stepsPerRun, 200);
  EXPECT_EQ(solver.stepsTaken(), 1 + timing.warmupSteps + 2 * timing.stepsPerRun);
  EXPECT_NEAR(timing.mlups, 1000.0 / (timing.msPerStep * 1e3), 1e-9 * timing.mlups);
}

TEST(StepTiming, AFastReferenceKeepsTheStepsAsked)
{
  BenchSettings settings = referenceSettings(quick());
  settings.steps = 10;  // a run of them would take 0.4 s only at 40 ms a step
  SlowSteps solver(0.0);
  EXPECT_EQ(timeSteps(solver, settings, 1.0).stepsPerRun, 10);
}

}  // namespace
}  // namespace lbmshape
