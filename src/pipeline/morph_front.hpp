// Which bricks of a narrow-band morph its moving surface comes near, step
// by step, so that the others are held whole (BandSolver::setHeldBricks)
// and cost a fraction of a streaming brick.
//
// Where diffusion is negligible the morph force alone moves X, and then
// X - X_target shrinks by r(Cs) = (1 - Cs/2) / (1 + Cs/2) a step
// (morph_schedule.hpp): after n steps X = X_T + (X_A - X_T) D_n, D_n the
// product of r over the schedule's first n steps. A cell's X is within W
// of zero for an interval of D (X is linear in D), a brick's for the hull
// of its cells' intervals, and since D only falls, for one run of steps.
// During those steps (with a margin for the distance diffusion moves the
// surface from that prediction) the brick streams as initialize()'s flags
// say; before them and after, it is held whole. Held cells are what the
// band held beyond its streaming cells before: X following the force
// alone, which is the prediction itself.
//
// A held brick that no streaming brick touches (of its 26 neighbours and
// itself, none streams in this step or the next) is frozen: no step reads
// or writes it until it thaws and catches up in one held step
// (lbm/frozen_bricks.hpp). Bricks with cells within `keepNearTarget` of
// the target's surface are never frozen: a frame's field is read there
// (the distance to the target), and a frozen brick's field is the one it
// froze with.
#pragma once

#include <cstdint>
#include <vector>

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/pipeline/morph_schedule.hpp"

namespace lbmshape {

class MorphFront {
public:
  // `streams` (one flag a stored cell, initialize()'s) says which cells may
  // stream at all; `reach` (positive, else std::invalid_argument) is how
  // near zero (voxels) a cell's predicted X makes its brick stream.
  MorphFront(const BandField& source, const BandField& target, const std::vector<uint8_t>& streams, double reach,
             const MorphSchedule& schedule, double keepNearTarget = 2.0);

  // One BrickMotion a brick slot (lbm/frozen_bricks.hpp): what the step
  // that starts after `step` steps does with the brick.
  std::vector<uint8_t> heldDuring(int step) const;
  // The first step after `step` whose motions differ from step's
  // (totalSteps when none): the steps up to it run as one batch.
  int sameUntil(int step) const;
  // The fraction of the bricks that stream, and that are frozen, averaged
  // over the steps.
  double meanStreamingFraction() const;
  double meanFrozenFraction() const;

private:
  std::vector<int> first_, last_;  // per slot: the first and last step it streams (first > last: never)
  // Per slot: the steps during which it may not freeze, from the first
  // step before one of its 27 bricks streams to the last that one streams
  // (from > to: none).
  std::vector<int> awakeFrom_, awakeTo_;
  std::vector<uint8_t> nearTarget_;  // per slot: never frozen
  int totalSteps_;
};

}  // namespace lbmshape
