#include "lbmshape/lbm/band_state.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lbmshape/lbm/frozen_bricks.hpp"
#include "lbmshape/lbm/relaxation.hpp"

namespace lbmshape::band_state {

std::vector<glm::vec4> collidedEquilibrium(const BandField& field, const std::optional<BandSource>& source)
{
  std::vector<glm::vec4> moments(field.values().size(), glm::vec4(0.0f));
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < moments.size(); ++i) moments[i].x = collidedDensity(field, source, i);
  return moments;
}

std::vector<uint8_t> onlyCellsInTheGrid(std::vector<uint8_t> streams, const BrickSet& bricks)
{
  const Extent3& e = bricks.cells();
#pragma omp parallel for schedule(static)
  for (size_t s = 0; s < bricks.activeCount(); ++s) {
    // Only the bricks at the grid's far faces reach beyond it.
    const glm::ivec3 end = brickEdge * (bricks.brick(int32_t(s)) + 1);
    if (end.x <= e.nx && end.y <= e.ny && end.z <= e.nz) continue;
    for (int local = 0; local < brickCells; ++local) {
      const glm::ivec3 c = bricks.cell(int32_t(s), local);
      if (!e.contains(c.x, c.y, c.z)) streams[s * brickCells + size_t(local)] = 0;
    }
  }
  return streams;
}

std::vector<int32_t> slotsToStep(const BrickSet& bricks, const std::vector<uint8_t>& streams, bool source)
{
  std::vector<int32_t> slots;
  for (size_t s = 0; s < bricks.activeCount(); ++s) {
    const auto first = streams.begin() + std::ptrdiff_t(s * brickCells);
    if (source || std::any_of(first, first + brickCells, [](uint8_t streams) { return streams != 0; }))
      slots.push_back(int32_t(s));
  }
  return slots;
}

std::vector<float> omegaFromGamma(const BandField& gamma)
{
  const std::vector<float>& g = gamma.values();
  std::vector<float> omega(g.size());
  // Checked in parallel, the first bad value reported after the loop: an
  // exception may not leave an OpenMP loop.
  size_t firstBad = g.size();
#pragma omp parallel for schedule(static) reduction(min : firstBad)
  for (size_t i = 0; i < g.size(); ++i) {
    if (relaxation::acceptableGamma(g[i]))
      omega[i] = relaxation::singlePrecisionOmega(g[i]);
    else
      firstBad = std::min(firstBad, i);
  }
  if (firstBad < g.size()) relaxation::checkGamma(g[firstBad], "per-cell gamma");
  return omega;
}

void checkStoredField(int back, int stepsTaken, bool source)
{
  if (back != 1 && back != 2) throw std::logic_error("the stored field is 1 or 2 steps back");
  if (stepsTaken < back) throw std::logic_error("the stored field needs as many steps taken as it goes back");
  if (source) throw std::logic_error("with a source, rho* is not the field");
}

void checkRestart(bool fieldHeld, bool workHasSource, bool source)
{
  if (!fieldHeld) throw std::logic_error("a restart needs the initial field held (holdFieldForRestart())");
  if (workHasSource != source)
    throw std::logic_error("a restart keeps the cells a step updates: set or clear the source before initialize()");
}

void checkHeldBricks(const std::vector<uint8_t>& heldPerSlot, const BrickSet& bricks)
{
  if (!heldPerSlot.empty() && heldPerSlot.size() != bricks.activeCount())
    throw std::invalid_argument("one held flag a brick slot, or none");
  for (uint8_t motion : heldPerSlot)
    if (motion > uint8_t(BrickMotion::Frozen))
      throw std::invalid_argument("a brick streams (0), is held (1) or frozen (2), not " + std::to_string(motion));
}

void checkSameBricks(const BrickSet& bricks, const BandField& field, const char* what)
{
  if (&field.bricks() != &bricks &&
      (field.bricks().activeCount() != bricks.activeCount() || !(field.bricks().cells() == bricks.cells())))
    throw std::invalid_argument(std::string("the ") + what + " lies on other bricks than the solver's");
}

}  // namespace lbmshape::band_state

namespace lbmshape {

std::vector<uint8_t> streamingCells(const BandField& field, double halfWidth)
{
  const BrickSet& bricks = field.bricks();
  std::vector<uint8_t> streams(field.values().size(), 0);
#pragma omp parallel for schedule(static)
  for (size_t s = 0; s < bricks.activeCount(); ++s)
    for (int local = 0; local < brickCells; ++local) {
      const glm::ivec3 c = bricks.cell(int32_t(s), local);
      const size_t i = s * brickCells + size_t(local);
      streams[i] = bricks.cells().contains(c.x, c.y, c.z) && std::abs(field.values()[i]) < halfWidth;
    }
  return streams;
}

}  // namespace lbmshape
