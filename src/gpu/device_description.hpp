// What `lbmshape info` reports about a Vulkan device, and what device
// selection and the memory checks look at: plain data, no Vulkan headers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lbmshape::gpu {

struct DeviceDescription {
  uint32_t index = 0;  // position in vkEnumeratePhysicalDevices
  std::string name;
  std::string type;               // "discrete", "integrated", "virtual", "cpu", "other"
  std::string driver;             // driver name and info, e.g. "llvmpipe (Mesa 22.3.6 ...)"
  std::string apiVersion;         // "1.3.230"
  uint64_t deviceLocalBytes = 0;  // largest DEVICE_LOCAL heap
  uint64_t maxStorageBufferRange = 0;
  uint64_t maxTexelBufferElements = 0;
  uint64_t maxAllocationBytes = 0;
  uint32_t maxWorkgroupCount[3] = {0, 0, 0};

  // The CPU (lavapipe): the device's memory is the host's, and a copy
  // between them crosses no bus.
  bool isCpu() const { return type == "cpu"; }
};

// Lower is better: discrete GPUs first, the CPU (lavapipe) as the fallback.
int typePreference(const std::string& type);

// Index into `devices` of the device to use: `request` is empty (best by
// type), a number (the device index), or part of a device name (any case).
// Throws UsageError naming the devices when nothing matches.
size_t chooseDevice(const std::vector<DeviceDescription>& devices, const std::string& request);

}  // namespace lbmshape::gpu
