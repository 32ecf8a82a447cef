// The lattice Boltzmann solver on a Vulkan device (shaders/lbm_*.comp).
#pragma once

#include <memory>

#include "lbmshape/lbm/lattice_solver.hpp"

namespace lbmshape {

namespace gpu {
class GpuContext;
}

class VulkanSolver final : public LatticeSolver {
public:
  // Checks that the lattice fits the device before allocating anything.
  VulkanSolver(gpu::GpuContext& context, Extent3 extent);
  ~VulkanSolver() override;

  std::string backendName() const override;
  Extent3 extent() const override;
  void setUniformGamma(double gamma) override;
  void setGammaPerCell(const Volume& gamma) override;
  // On the device, in one submission: no field read back, no gamma sent
  // (shaders/lbm_feature_rule.comp).
  void setFeaturePreservingGamma(double gamma0, double kappaEdge) override;
  void setPaperRule(double gamma0) override;
  void setSource(std::optional<LinearSource> source) override;
  void setSourceStrength(float decay, float scale) override;
  void initialize(const Volume& field) override;
  void step(int count) override;
  int stepsTaken() const override;
  Volume field() override;
  void fieldInto(Volume& out) override;
  void fieldIntoThenStep(Volume& out, std::optional<SourceStrength> next) override;
  Volume previousField() override;

private:
  struct Resources;
  std::unique_ptr<Resources> r_;
};

}  // namespace lbmshape
