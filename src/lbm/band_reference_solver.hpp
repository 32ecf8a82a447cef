// The narrow-band lattice (band_solver.hpp) on the CPU: the reference the
// Vulkan solver is tested against.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/lbm/band_solver.hpp"
#include "lbmshape/lbm/frozen_bricks.hpp"

namespace lbmshape {

class BandReferenceSolver final : public BandSolver {
public:
  explicit BandReferenceSolver(std::shared_ptr<const BrickSet> bricks);

  std::string backendName() const override { return "reference (band)"; }
  const BrickSet& bricks() const override { return *bricks_; }
  void setUniformGamma(double gamma) override;
  void setGammaPerCell(const BandField& gamma) override;
  void setPaperRule(double gamma0) override;
  void setSource(std::optional<BandSource> source) override;
  void setSourceStrength(float decay, float scale) override;
  void setHeldBricks(std::vector<uint8_t> heldPerSlot) override;
  using BandSolver::initialize;
  void initialize(BandField field, std::vector<uint8_t> streams) override;
  void holdFieldForRestart() override;
  void restart() override;
  void step(int count) override;
  int stepsTaken() const override { return steps_; }
  BandField field() override;
  BandField previousField() override;
  BandField storedField(int back) override;
  double surfaceSpeed() override;

protected:
  const BandField* sourceBase() const override { return source_ ? &source_->base : nullptr; }

private:
  template <bool Collide>
  void sweep(std::vector<float>* fieldOut);
  // The paper's rule before a step's collision: gamma and omega per cell
  // from the X the step pulls (setPaperRule).
  void applyPaperRule();
  // The bricks that freeze before the next `count` steps: their field kept.
  void freezeBeforeSteps(int count);
  // X from the sum of cell i's pulled f under the source at decay and
  // scale (solved exactly for S = scale base - decay X), and S; without a
  // source X is the sum and S 0 (band_step.glsl's fieldFromSum).
  struct Sourced {
    float X, S;
  };
  Sourced withSource(float sum, size_t i, float decay, float scale) const;
  // A held step of a cell whose moments are `own` (cell i) under decay (and
  // scale) c and omega (FrozenBricks::CatchUp).
  glm::vec4 heldStep(glm::vec4 own, size_t i, float c, float omega) const;
  std::vector<glm::vec4>& copy(int k) { return k == currentCopy_ ? current_ : next_; }

  std::shared_ptr<const BrickSet> bricks_;
  std::vector<int32_t> neighbours_;        // 27 a slot (BrickSet::neighbourTable)
  std::vector<glm::vec4> current_, next_;  // (rho*, j*) a cell
  std::vector<uint8_t> streams_;           // 1: the cell streams; 0: held (or beyond the grid)
  std::vector<int32_t> work_;              // the slots a step updates (band_state::slotsToStep)
  BandField initial_;                      // X at initialisation, with its far sides
  float uniformOmega_ = 1.0f;
  std::vector<uint8_t> heldSlots_;  // setHeldBricks: BrickMotion a slot
  FrozenBricks frozen_;
  std::vector<float> frozenField_;   // the field of the frozen bricks' cells, as they froze
  int currentCopy_ = 0;              // which of the two copies current_ is (they swap at each step)
  std::vector<float> omegaPerCell_;  // empty: uniform
  std::optional<double> paperRuleGamma0_;
  bool paperRuleReady_ = false;      // initialize() has seeded the rule's state
  BandField xBefore_, gammaBefore_;  // the paper's rule: what each cell's last step pulled and used
  std::optional<BandSource> source_;
  int steps_ = 0;
  bool workHasSource_ = false;  // whether work_ was made for a source
};

}  // namespace lbmshape
