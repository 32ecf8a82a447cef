// Times lattice Boltzmann steps on a back end: what `lbmshape bench` reports.
#pragma once

#include <string>

#include "lbmshape/core/extent.hpp"
#include "lbmshape/lbm/lattice_solver.hpp"

namespace lbmshape {

struct StepTiming {
  double msPerStep = 0.0;  // median over the timed runs
  double bestMsPerStep = 0.0;
  double firstStepMs = 0.0;  // includes the driver's shader compilation
  int warmupSteps = 0;       // run after the first, untimed, for settings.warmupMs
  int stepsPerRun = 0;       // settings.steps, or fewer within settings.longestRunMs
  double mlups = 0.0;        // million lattice updates per second (median)
  double gbps = 0.0;         // mlups * bytes per update
};

struct BenchSettings {
  int steps = 100;  // per timed run
  int runs = 5;     // the median of these is reported
  double gamma = 0.2;
  // Untimed steps before the runs, for at least this long: a GPU raises its
  // clocks only after a few hundred milliseconds of work (an H100 took
  // 0.40 ms a step of 128^3 in a cold 100-step run, 0.145 ms once warm).
  double warmupMs = 500.0;
  // When above 0, a timed run takes fewer than `steps` steps if the warm-up's
  // pace says it would last longer than this: see referenceSettings().
  double longestRunMs = 0.0;
};

// The settings the CPU reference is timed with: the user's, with runs of at
// most about 0.4 s and no warm-up beyond the first step. Where the device
// is a real GPU, the grid it steps in a few milliseconds takes the
// reference seconds a step; `bench --size 256,256,256` on an H100 spent
// over 30 s timing the reference alone. A rate needs no more steps than it
// takes to measure it.
BenchSettings referenceSettings(BenchSettings settings);

// Runs `settings.runs` times `settings.steps` steps on a random field after
// one warm-up step, and reports per-step figures.
StepTiming timeSolver(LatticeSolver& solver, const BenchSettings& settings);

// The timing itself, on an initialised solver of either kind: one step
// (firstStepMs), the warm-up, then the runs; mlups counts `cellsPerStep`
// updates a step.
StepTiming timeSteps(SteppingSolver& solver, const BenchSettings& settings, double cellsPerStep);

}  // namespace lbmshape
