// The Vulkan instance: loader, optional Khronos validation (whose messages are
// counted, so tests can fail on any of them), and the list of devices.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "lbmshape/gpu/device_description.hpp"

namespace lbmshape::gpu {

// Validation is on when asked for, or when the environment says
// LBMSHAPE_VALIDATION=1 (the test suite sets it for every test).
bool validationRequestedByEnvironment();

class VulkanInstance {
public:
  explicit VulkanInstance(bool validation);

  vk::raii::Instance& instance() { return instance_; }
  const std::vector<DeviceDescription>& devices() const { return devices_; }
  vk::raii::PhysicalDevice& physicalDevice(size_t i) { return physicalDevices_[i]; }

  bool validationEnabled() const { return messenger_.has_value(); }
  // Warnings and errors the validation layer has reported so far.
  int validationMessages() const { return validationMessages_->load(); }

private:
  vk::raii::Context context_;
  vk::raii::Instance instance_{nullptr};
  std::shared_ptr<std::atomic<int>> validationMessages_ = std::make_shared<std::atomic<int>>(0);
  std::optional<vk::raii::DebugUtilsMessengerEXT> messenger_;
  std::vector<vk::raii::PhysicalDevice> physicalDevices_;
  std::vector<DeviceDescription> devices_;
};

}  // namespace lbmshape::gpu
