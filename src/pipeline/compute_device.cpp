#include "pipeline/compute_device.hpp"

#include "core/error.hpp"
#include "gpu/gpu_context.hpp"
#include "gpu/vulkan_instance.hpp"
#include "lbm/band_reference_solver.hpp"
#include "lbm/band_vulkan_solver.hpp"
#include "lbm/lattice_memory.hpp"
#include "lbm/reference_solver.hpp"
#include "lbm/vulkan_solver.hpp"

namespace lbmshape {

ComputeDevice::ComputeDevice(const std::string& request, bool validation) : request_(request), validation_(validation) {}

ComputeDevice::~ComputeDevice() = default;
ComputeDevice::ComputeDevice(ComputeDevice&&) noexcept = default;

const gpu::DeviceDescription& ComputeDevice::description() const
{
  if (!instance_) {
    auto instance = std::make_shared<gpu::VulkanInstance>(validation_);
    chosen_ = gpu::chooseDevice(instance->devices(), request_);
    instance_ = std::move(instance);
  }
  return instance_->devices()[chosen_];
}

gpu::GpuContext* ComputeDevice::gpu() const
{
  if (isReference()) return nullptr;
  if (!gpu_) {
    description();
    gpu_ = std::make_unique<gpu::GpuContext>(instance_, chosen_);
  }
  return gpu_.get();
}

std::string ComputeDevice::name() const { return isReference() ? "reference (CPU)" : description().name; }

void ComputeDevice::checkFits(const Extent3& extent) const
{
  LatticeLayout layout = latticeLayout(extent);
  if (!isReference()) checkFitsDevice(layout, description());
}

std::unique_ptr<LatticeSolver> ComputeDevice::makeSolver(const Extent3& extent) const
{
  checkFits(extent);
  if (!isReference()) return std::make_unique<VulkanSolver>(*gpu(), extent);
  return std::make_unique<ReferenceSolver>(extent);
}

std::unique_ptr<BandSolver> ComputeDevice::makeBandSolver(std::shared_ptr<const BrickSet> bricks) const
{
  if (!isReference()) return std::make_unique<BandVulkanSolver>(*gpu(), std::move(bricks));
  return std::make_unique<BandReferenceSolver>(std::move(bricks));
}

void ComputeDevice::checkBandFits(const BrickSet& bricks, bool perCellOmega, bool source) const
{
  if (!isReference()) BandVulkanSolver::checkFits(bricks, description(), perCellOmega, source);
}

void ComputeDevice::requireCleanValidation() const
{
  const int messages = instance_ ? instance_->validationMessages() : 0;
  if (messages > 0)
    throw DeviceError("the Vulkan validation layer reported " + std::to_string(messages) + " problem(s), printed above");
}

void ComputeDevice::close()
{
  gpu_.reset();
  requireCleanValidation();
}

}  // namespace lbmshape
