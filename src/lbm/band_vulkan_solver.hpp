// The narrow-band lattice (band_solver.hpp) on a Vulkan device
// (shaders/band_step.comp), tested against BandReferenceSolver.
#pragma once

#include <climits>

#include <cstdint>
#include <memory>

#include "lbmshape/lbm/band_solver.hpp"

namespace lbmshape {

namespace gpu {
class GpuContext;
struct DeviceDescription;
}  // namespace gpu

class BandVulkanSolver final : public BandSolver {
public:
  // Host <-> device copies go through a staging buffer of at most
  // `stagingBytes` (at least one brick's moments), chunk by chunk: a staging
  // copy of the whole band, and the host arrays that would fill it, would
  // cost more memory than the lattice itself. The default holds the field of
  // 4 M cells (a band of 256^3), so most fields come back in one go.
  static constexpr uint64_t defaultStagingBytes = uint64_t(16) << 20;

  // Buffers written by the shaders split into pools of whole bricks of at
  // most `poolBytes` each (0: the device's storage-buffer range), one
  // binding a pool; the tests make them small to split a small band.
  BandVulkanSolver(gpu::GpuContext& context, std::shared_ptr<const BrickSet> bricks,
                   uint64_t stagingBytes = defaultStagingBytes, BandRunKind kind = {}, uint64_t poolBytes = 0);
  ~BandVulkanSolver() override;

  std::string backendName() const override;
  const BrickSet& bricks() const override;
  void setUniformGamma(double gamma) override;
  void setGammaPerCell(const BandField& gamma) override;
  void setPaperRule(double gamma0) override;
  void setFeaturePreservingGamma(double gamma0, double kappaEdge) override;
  void setSource(std::optional<BandSource> source) override;
  void setSourceStrength(float decay, float scale) override;
  void setHeldBricks(std::vector<uint8_t> heldPerSlot) override;
  using BandSolver::initialize;
  void initialize(BandField field, std::vector<uint8_t> streams) override;
  void holdFieldForRestart() override;
  void restart() override;
  void step(int count) override;
  int stepsTaken() const override;
  BandField field() override;
  void fieldInto(BandField& out) override;
  void fieldIntoThenStep(BandField& out, std::optional<SourceStrength> next) override;
  BandField previousField() override;
  BandField storedField(int back) override;
  double surfaceSpeed() override;
  SurfacePieces surfacePieces(const SurfaceRequest& request) override;
  SurfacePieces surfacePiecesThenStep(const SurfaceRequest& request, std::optional<SourceStrength> next) override;

  // Bytes the solver keeps on the device per stored cell (both copies of
  // the moments, the field, the brick tables, and per-cell omega or source
  // if set).
  static double deviceBytesPerCell(bool perCellOmega, bool source);
  // The most cells a band may store on `device`: its buffers split into at
  // most BAND_MAX_POOLS bindings within the storage-buffer range, the
  // moments are read through one texel buffer and each copy of them is one
  // allocation, and all of it, staging included, fits the device's memory.
  // The constructor throws DeviceError beyond it.
  static uint64_t maxCells(const gpu::DeviceDescription& device, bool perCellOmega, bool source);
  // Throws DeviceError when a band on `bricks` exceeds maxCells(), saying
  // what it needs and about what grid would fit.
  // The grid named is at most `cap` along its longest side (the host's, for
  // a device that is the CPU: memory_sizes.hpp).
  static void checkFits(const BrickSet& bricks, const gpu::DeviceDescription& device, bool perCellOmega, bool source,
                        int cap = INT32_MAX);
  // The longest side checkFits names for a band like `bricks`'s.
  static int longestSideThatFits(const BrickSet& bricks, const gpu::DeviceDescription& device, bool perCellOmega,
                                 bool source);

private:
  void startFrom(BandField field);

  struct Resources;
  std::unique_ptr<Resources> r_;
};

}  // namespace lbmshape
