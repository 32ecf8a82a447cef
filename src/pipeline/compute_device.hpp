// Where the lattice runs: a Vulkan device, or the CPU reference solver
// (--device reference). Jobs in one process share it, and with it the
// compiled pipelines.
#pragma once

#include <memory>
#include <string>

#include "core/extent.hpp"
#include "lbm/lattice_solver.hpp"

namespace lbmshape {

namespace gpu {
class GpuContext;
}

class ComputeDevice {
public:
  // `request`: empty (the best device), an index, part of a device name, or
  // "reference". Throws UsageError when nothing matches, DeviceError when
  // Vulkan is unusable.
  ComputeDevice(const std::string& request, bool validation);
  ~ComputeDevice();
  ComputeDevice(ComputeDevice&&) noexcept;

  std::string name() const;
  bool isReference() const { return !gpu_; }
  gpu::GpuContext* gpu() const { return gpu_.get(); }

  // A solver for a lattice of this size; throws UsageError when it does not
  // fit the device, before allocating anything.
  std::unique_ptr<LatticeSolver> makeSolver(const Extent3& extent) const;
  // The same check alone, for validating a job before its expensive stages.
  void checkFits(const Extent3& extent) const;

  // With validation on, throws DeviceError if the layer reported anything.
  void requireCleanValidation() const;

private:
  std::unique_ptr<gpu::GpuContext> gpu_;
};

}  // namespace lbmshape
