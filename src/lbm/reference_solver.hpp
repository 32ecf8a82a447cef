// The CPU reference of the lattice step: plain C++ threaded with OpenMP, the
// same arithmetic in the same order as shaders/lbm_step.comp. It is the oracle
// of the GPU tests and the `--device reference` back end.
#pragma once

#include <vector>

#include "lbmshape/lbm/lattice_solver.hpp"

namespace lbmshape {

class ReferenceSolver final : public LatticeSolver {
public:
  explicit ReferenceSolver(Extent3 extent);

  std::string backendName() const override { return "reference (CPU)"; }
  Extent3 extent() const override { return extent_; }
  void setUniformGamma(double gamma) override;
  void setGammaPerCell(const Volume& gamma) override;
  void setPaperRule(double gamma0) override;
  void setSource(std::optional<LinearSource> source) override;
  void setSourceStrength(float decay, float scale) override;
  void initialize(const Volume& field) override;
  void step(int count) override;
  int stepsTaken() const override { return steps_; }
  Volume field() override;
  Volume previousField() override;

private:
  template <bool Collide>
  void sweep(Volume* fieldOut);
  // The paper's rule before a step's collision: gamma and omega per cell
  // from the X the step pulls (setPaperRule).
  void applyPaperRule();

  float* distribution(std::vector<float>& lattice, int i) { return lattice.data() + size_t(i) * extent_.cells(); }

  Extent3 extent_;
  std::vector<float> current_, next_;  // post-collision f*, structure of arrays
  float uniformOmega_ = 1.0f;
  Volume omegaPerCell_;  // empty when uniform
  std::optional<double> paperRuleGamma0_;
  bool paperRuleReady_ = false;   // initialize() has seeded the rule's state
  Volume xBefore_, gammaBefore_;  // the paper's rule: what each cell's last step pulled and used
  std::optional<LinearSource> source_;
  int steps_ = 0;
};

}  // namespace lbmshape
