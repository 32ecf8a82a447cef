#include "pipeline/compute_device.hpp"

#include "core/error.hpp"
#include "gpu/gpu_context.hpp"
#include "lbm/lattice_memory.hpp"
#include "lbm/reference_solver.hpp"
#include "lbm/vulkan_solver.hpp"

namespace lbmshape {

ComputeDevice::ComputeDevice(const std::string& request, bool validation)
{
  if (request != "reference") gpu_ = std::make_unique<gpu::GpuContext>(gpu::GpuOptions{request, validation});
}

ComputeDevice::~ComputeDevice() = default;
ComputeDevice::ComputeDevice(ComputeDevice&&) noexcept = default;

std::string ComputeDevice::name() const { return gpu_ ? gpu_->description().name : "reference (CPU)"; }

void ComputeDevice::checkFits(const Extent3& extent) const
{
  LatticeLayout layout = latticeLayout(extent);
  if (gpu_) checkFitsDevice(layout, gpu_->description());
}

std::unique_ptr<LatticeSolver> ComputeDevice::makeSolver(const Extent3& extent) const
{
  checkFits(extent);
  if (gpu_) return std::make_unique<VulkanSolver>(*gpu_, extent);
  return std::make_unique<ReferenceSolver>(extent);
}

void ComputeDevice::requireCleanValidation() const
{
  if (gpu_ && gpu_->validationMessages() > 0)
    throw DeviceError("the Vulkan validation layer reported " + std::to_string(gpu_->validationMessages()) +
                      " problem(s), printed above");
}

}  // namespace lbmshape
