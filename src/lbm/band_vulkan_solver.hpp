// The narrow-band lattice (band_solver.hpp) on a Vulkan device
// (shaders/band_step.comp), tested against BandReferenceSolver.
#pragma once

#include <memory>

#include "lbm/band_solver.hpp"

namespace lbmshape {

namespace gpu {
class GpuContext;
}

class BandVulkanSolver final : public BandSolver {
public:
  // Throws DeviceError when the device lacks buffer device addresses.
  BandVulkanSolver(gpu::GpuContext& context, std::shared_ptr<const BrickSet> bricks);
  ~BandVulkanSolver() override;

  std::string backendName() const override;
  const BrickSet& bricks() const override;
  void setUniformGamma(double gamma) override;
  void setGammaPerCell(const BandField& gamma) override;
  void setSource(std::optional<BandSource> source) override;
  using BandSolver::initialize;
  void initialize(const BandField& field, std::vector<uint8_t> streams) override;
  void step(int count) override;
  int stepsTaken() const override;
  BandField field() override;

  // Bytes the solver keeps on the device per stored cell (both copies of
  // the moments, the streaming bits, and per-cell omega or source if set).
  static double deviceBytesPerCell(bool perCellOmega, bool source);

private:
  struct Resources;
  std::unique_ptr<Resources> r_;
};

}  // namespace lbmshape
