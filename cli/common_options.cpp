#include "common_options.hpp"

#include <iostream>

#include "lbmshape/core/log.hpp"

namespace lbmshape::cli {

ComputeDevice& CommonOptions::computeDevice() const
{
  if (!device_) {
    device_ = std::make_shared<ComputeDevice>(device, validation, distances, surfaces);
    if (device_->isReference()) log::verbose("device: " + device_->name());  // a Vulkan device logs itself when opened
  }
  return *device_;
}

void CommonOptions::closeDevice() const
{
  if (device_) device_->close();
}

void printJson(const nlohmann::json& document)
{
  // Messages may quote bytes of a file that are not UTF-8: replaced, not thrown.
  std::cout << document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl;
}

}  // namespace lbmshape::cli
