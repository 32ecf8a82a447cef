#include "common_options.hpp"

#include <iostream>

#include "core/error.hpp"
#include "core/log.hpp"

namespace lbmshape::cli {

ComputeDevice& CommonOptions::computeDevice() const
{
  if (!device_) {
    device_ = std::make_shared<ComputeDevice>(device, validation);
    log::verbose("device: " + device_->name());
  }
  return *device_;
}

std::unique_ptr<gpu::GpuContext> openDevice(const CommonOptions& options)
{
  return std::make_unique<gpu::GpuContext>(gpu::GpuOptions{options.device, options.validation});
}

void requireCleanValidation(const gpu::GpuContext& context)
{
  if (context.validationMessages() > 0)
    throw DeviceError("the Vulkan validation layer reported " + std::to_string(context.validationMessages()) +
                      " problem(s), printed above");
}

void printJson(const nlohmann::json& document) { std::cout << document.dump(2) << std::endl; }

}  // namespace lbmshape::cli
