// Bricks a narrow-band step skips altogether (BandSolver::setHeldBricks's
// BrickMotion::Frozen), and what it takes to bring one back: the
// bookkeeping both band solvers share, so that the CPU reference and the
// Vulkan solver skip and catch up alike.
//
// A held brick pulls from itself: with a source S = c (base - X) (scale
// equal to decay, as a morph's) each step moves rho* - base by
// r(c) = (1 - c/2) / (1 + c/2) and j* by (1 - omega), whatever the other
// bricks do. So the k steps a frozen brick missed are one held step with
// r(c_eff) = prod r(c_j), that is c_eff = 2 (1 - R) / (1 + R), and
// 1 - omega_eff = prod (1 - omega_j): the catch-up, run when the brick
// thaws. No neighbour may read a frozen brick in between (a brick freezes
// only where nothing streams next to it), so it is the same state up to
// rounding.
//
// Its field stays what it was when it froze: X of the state it froze with,
// under the source of that moment. A morph freezes only bricks far from
// every surface it draws and from the target's, where no frame reads it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lbmshape {

// What a step does with a brick (BandSolver::setHeldBricks, one a slot).
enum class BrickMotion : uint8_t {
  Streams = 0,  // as initialize()'s flags say
  Held = 1,     // every cell pulls from itself
  Frozen = 2,   // not updated at all; caught up when it thaws
};

class FrozenBricks {
public:
  // The parameters of one step, as the catch-up needs them.
  struct StepParameters {
    bool source = false;
    float decay = 0.0f, scale = 1.0f, omega = 1.0f;
    bool perCellOmega = false, paperRule = false;
  };
  // A held step that brings `slots` from the state after step `since` (in
  // copy `copy` of the moments) to the state after the steps taken now.
  struct CatchUp {
    int since = 0, copy = 0;
    float decay = 0.0f;  // c_eff, also the source's scale
    float omega = 0.0f;  // omega_eff
    std::vector<int32_t> slots;
  };

  explicit FrozenBricks(size_t slots) : since_(slots, -1), copy_(slots, 0) {}

  // A new start (initialize(), restart()): nothing frozen, every step
  // forgotten; the slots flagged frozen freeze at the first real step.
  void start();

  // Before `count` steps from the state after `stepsTaken`, the current
  // copy `current`: the slots frozen from now on and not yet skipped, whose
  // field the solver writes (X of the state they freeze with) before the
  // steps, are returned; from now on they count as frozen. Throws
  // std::logic_error when a brick is frozen under parameters the catch-up
  // cannot follow: omega per cell, the paper's rule, a source whose scale
  // is not its decay.
  std::vector<int32_t> beforeSteps(int count, const StepParameters& p, int stepsTaken, int current);

  // New flags (BandSolver::setHeldBricks): the slots that thaw, grouped by
  // the state they hold, with the held step that catches each group up to
  // the state after `stepsTaken` (nothing to do for a slot already there).
  // A slot newly flagged frozen is skipped from the next step on.
  std::vector<CatchUp> setMotion(const std::vector<uint8_t>& motion, int stepsTaken);

  // Whether slot s is skipped now (flagged frozen, and a step has run since).
  bool frozen(size_t s) const { return since_[s] >= 0; }
  size_t frozenCount() const { return frozenCount_; }
  // Whether the next step freezes a slot (flagged frozen, not yet frozen).
  bool freezingNext() const;

private:
  std::vector<uint8_t> motion_;   // the flags set
  std::vector<int> since_;        // per slot: the state it holds (steps taken), -1 when not frozen
  std::vector<uint8_t> copy_;     // per frozen slot: the copy of the moments holding it
  std::vector<double> keepRho_;   // per step n (the state after n steps): r(c) of the step that made it
  std::vector<double> keepFlux_;  // and its 1 - omega
  size_t frozenCount_ = 0;
};

}  // namespace lbmshape
