// Host-side work both narrow-band solvers share: the state initialize()
// starts from, and which cells stream.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/lbm/band_solver.hpp"

namespace lbmshape::band_state {

// The moments (rho*, j*) after one collision of the equilibrium
// f_i = w_i (X - S/2): what a grid solver holds after its first step, whose
// streaming delivers every cell its own equilibrium. rho* = X + S/2 with
// S = A - c X, j* = 0: omega does not enter.
std::vector<glm::vec4> collidedEquilibrium(const BandField& field, const std::optional<BandSource>& source);

// rho* of stored cell i alone, for a solver that lays the moments out itself.
inline float collidedDensity(const BandField& field, const std::optional<BandSource>& source, size_t i)
{
  const float X = field.values()[i];
  const float S = source ? source->scale * source->base.values()[i] - source->decay * X : 0.0f;
  return X + 0.5f * S;
}

// `streams` with the cells beyond the grid (in bricks at its far faces)
// cleared: they never stream, whatever the caller flagged.
std::vector<uint8_t> onlyCellsInTheGrid(std::vector<uint8_t> streams, const BrickSet& bricks);

// The slots a step must update: all of them with a source (held cells
// follow it), else only those with a streaming cell: a brick of held cells
// alone keeps its moments, step after step.
std::vector<int32_t> slotsToStep(const BrickSet& bricks, const std::vector<uint8_t>& streams, bool source);

// omega per cell from gamma per cell, checking every value, as on the grid.
std::vector<float> omegaFromGamma(const BandField& gamma);

// Throws std::logic_error unless storedField(back) can be read: 1 or 2
// steps back, at least that many steps taken, no source.
void checkStoredField(int back, int stepsTaken, bool source);
// Throws std::logic_error when BandSolver::restart() cannot start again:
// the initial field is gone, or the source was set or cleared since the
// cells a step updates were chosen.
void checkRestart(bool fieldHeld, bool workHasSource, bool source);

// Throws std::invalid_argument unless `heldPerSlot` (BandSolver::setHeldBricks)
// is empty or has one flag a brick of `bricks`.
void checkHeldBricks(const std::vector<uint8_t>& heldPerSlot, const BrickSet& bricks);
// Throws std::invalid_argument unless `field` lies on `bricks`.
void checkSameBricks(const BrickSet& bricks, const BandField& field, const char* what);

}  // namespace lbmshape::band_state
