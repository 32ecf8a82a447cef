#include "lbmshape/bench/band_bench.hpp"

#include <algorithm>
#include <cmath>

#include "lbmshape/lbm/band_state.hpp"

namespace lbmshape {

BandBenchCase sphereBand(const Extent3& extent, double halfWidth,
                         const std::function<void(const BrickSet&)>& checkBricks)
{
  const glm::dvec3 centre = 0.5 * (glm::dvec3(extent.nx, extent.ny, extent.nz) - 1.0);
  const double radius = 0.4 * std::min({extent.nx, extent.ny, extent.nz});
  const double reach = halfWidth + 2.0;
  auto bricks = std::make_shared<BrickSet>(extent);
  const Extent3 grid = bricks->bricks();
  for (int bz = 0; bz < grid.nz; ++bz)
    for (int by = 0; by < grid.ny; ++by)
      for (int bx = 0; bx < grid.nx; ++bx) {
        // The brick's cells span [lo, hi]; the sphere's distance |r - |p - c||
        // over the box is within reach when the box's nearest and farthest
        // points from c straddle [radius - reach, radius + reach].
        const glm::dvec3 lo = glm::dvec3(brickEdge * glm::ivec3(bx, by, bz)), hi = lo + double(brickEdge - 1);
        const glm::dvec3 nearest = glm::clamp(centre, lo, hi);
        const glm::dvec3 farthest = glm::mix(lo, hi, glm::dvec3(glm::lessThan(centre, 0.5 * (lo + hi))));
        if (glm::length(nearest - centre) <= radius + reach && glm::length(farthest - centre) >= radius - reach)
          bricks->activate(bx, by, bz);
      }
  if (checkBricks) checkBricks(*bricks);
  BandBenchCase band;
  band.halfWidth = halfWidth;
  band.field = BandField(bricks, float(reach + brickEdge * std::sqrt(3.0)));
  std::vector<float>& values = band.field.values();
  for (size_t i = 0; i < values.size(); ++i) {
    const glm::ivec3 c = bricks->cell(int32_t(i / brickCells), int(i % brickCells));
    values[i] = float(radius - glm::length(glm::dvec3(c) - centre));
  }
  for (int bz = 0; bz < grid.nz; ++bz)
    for (int by = 0; by < grid.ny; ++by)
      for (int bx = 0; bx < grid.nx; ++bx) {
        const glm::dvec3 middle = glm::dvec3(brickEdge * glm::ivec3(bx, by, bz)) + 0.5 * (brickEdge - 1);
        band.field.farSides()[grid.index(bx, by, bz)] = glm::length(middle - centre) < radius ? 1 : -1;
      }
  const std::vector<uint8_t> streams = band_state::onlyCellsInTheGrid(streamingCells(band.field, halfWidth), *bricks);
  band.streamingCells = size_t(std::count(streams.begin(), streams.end(), uint8_t(1)));
  band.steppedCells = band_state::slotsToStep(*bricks, streams, false).size() * brickCells;
  return band;
}

BandStepTiming timeBandSolver(BandSolver& solver, const BandBenchCase& band, const BenchSettings& settings)
{
  solver.setUniformGamma(settings.gamma);
  solver.initialize(band.field, band.halfWidth);
  solver.step(1);  // the state initialize() leaves counts as the first step

  BandStepTiming timing;
  timing.perStep = timeSteps(solver, settings, double(band.steppedCells));
  const StepTiming& t = timing.perStep;
  timing.storedMlups = double(band.field.values().size()) / (t.msPerStep * 1e3);
  return timing;
}

}  // namespace lbmshape
