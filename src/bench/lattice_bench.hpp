// Times lattice Boltzmann steps on a back end: what `lbmshape bench` reports.
#pragma once

#include <string>

#include "core/extent.hpp"
#include "lbm/lattice_solver.hpp"

namespace lbmshape {

struct StepTiming {
  double msPerStep = 0.0;  // median over the timed runs
  double bestMsPerStep = 0.0;
  double firstStepMs = 0.0;  // includes the driver's shader compilation
  int warmupSteps = 0;       // run after the first, untimed, for settings.warmupMs
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
};

// Runs `settings.runs` times `settings.steps` steps on a random field after
// one warm-up step, and reports per-step figures.
StepTiming timeSolver(LatticeSolver& solver, const BenchSettings& settings);

// The timing itself, on an initialised solver of either kind: one step
// (firstStepMs), the warm-up, then the runs; mlups counts `cellsPerStep`
// updates a step.
StepTiming timeSteps(SteppingSolver& solver, const BenchSettings& settings, double cellsPerStep);

}  // namespace lbmshape
