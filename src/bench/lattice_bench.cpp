#include "lbmshape/bench/lattice_bench.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/lbm/lattice_memory.hpp"

namespace lbmshape {

StepTiming timeSolver(LatticeSolver& solver, const BenchSettings& settings)
{
  const Extent3 extent = solver.extent();
  Volume field(extent);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  for (size_t i = 0; i < field.size(); ++i) field[i] = value(rng);
  solver.setUniformGamma(settings.gamma);
  solver.initialize(field);

  StepTiming timing = timeSteps(solver, settings, double(extent.cells()));
  timing.gbps = timing.mlups * 1e6 * double(LatticeLayout::bytesPerUpdate) / 1e9;
  return timing;
}

BenchSettings referenceSettings(BenchSettings settings)
{
  settings.longestRunMs = 400.0;
  settings.warmupMs = 0.0;  // a CPU's clocks need no half second to rise; the first step still goes untimed
  return settings;
}

StepTiming timeSteps(SteppingSolver& solver, const BenchSettings& settings, double cellsPerStep)
{
  StepTiming timing;
  Stopwatch first;
  solver.step(1);
  timing.firstStepMs = first.ms();
  Stopwatch warm;
  // A stop is honoured between steps and runs: one run of the user's
  // --steps is the longest wait.
  const std::string nothingPrinted = "the timing was stopped before its figures";
  interrupt::check(nothingPrinted);
  while (warm.ms() < settings.warmupMs) {
    solver.step(1);
    ++timing.warmupSteps;
    interrupt::check(nothingPrinted);
  }
  const double warmMs = warm.ms();

  timing.stepsPerRun = settings.steps;
  if (settings.longestRunMs > 0.0) {
    const double pace = timing.warmupSteps > 0 ? warmMs / timing.warmupSteps : timing.firstStepMs;
    const double fit = std::floor(settings.longestRunMs / std::max(pace, 1e-6));
    timing.stepsPerRun = int(std::clamp(fit, 1.0, double(settings.steps)));
  }
  std::vector<double> perStep;
  for (int r = 0; r < settings.runs; ++r) {
    Stopwatch watch;
    solver.step(timing.stepsPerRun);
    perStep.push_back(watch.ms() / timing.stepsPerRun);
    interrupt::check(nothingPrinted);
  }
  std::sort(perStep.begin(), perStep.end());
  timing.msPerStep = perStep[perStep.size() / 2];
  timing.bestMsPerStep = perStep.front();
  timing.mlups = cellsPerStep / (timing.msPerStep * 1e3);
  return timing;
}

}  // namespace lbmshape
