// Times the narrow-band lattice (lbm/band_solver.hpp) on a back end: what
// `lbmshape bench --band` reports. The band is the one a denoise would make
// around a sphere filling the grid, so its cost follows the sphere's area as
// a real surface's would.
#pragma once

#include <functional>
#include <memory>

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/bench/lattice_bench.hpp"
#include "lbmshape/lbm/band_solver.hpp"

namespace lbmshape {

struct BandBenchCase {
  BandField field;          // the sphere's signed distance on the band's bricks
  double halfWidth = 0.0;   // cells within it stream
  size_t steppedCells = 0;  // cells of the bricks a step updates
  size_t streamingCells = 0;
};

// A sphere of radius 0.4 x the shortest side, centred in `extent`, on the
// bricks within halfWidth + 2 of it (as a denoise chooses them);
// `checkBricks` sees the bricks before their cells are allocated.
BandBenchCase sphereBand(const Extent3& extent, double halfWidth,
                         const std::function<void(const BrickSet&)>& checkBricks = {});

struct BandStepTiming {
  StepTiming perStep;        // MLUPS on the stepped cells
  double storedMlups = 0.0;  // on every stored cell: the band's whole volume per second
};

// Runs `settings.runs` times `settings.steps` steps after one warm-up step.
BandStepTiming timeBandSolver(BandSolver& solver, const BandBenchCase& band, const BenchSettings& settings);

}  // namespace lbmshape
