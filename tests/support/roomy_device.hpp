// A made-up Vulkan device with room for anything, whose limits the tests of
// the fit checks lower one at a time.
#pragma once

#include <cstdint>

#include "lbmshape/gpu/device_description.hpp"

namespace lbmshape::testing {

inline gpu::DeviceDescription roomyDevice()
{
  gpu::DeviceDescription d;
  d.name = "test device";
  d.type = "discrete";
  d.deviceLocalBytes = uint64_t(1) << 40;
  d.maxStorageBufferRange = uint64_t(1) << 40;
  d.maxTexelBufferElements = uint64_t(1) << 40;
  d.maxAllocationBytes = uint64_t(1) << 40;
  d.maxWorkgroupCount[0] = d.maxWorkgroupCount[1] = d.maxWorkgroupCount[2] = 1u << 30;
  return d;
}

}  // namespace lbmshape::testing
