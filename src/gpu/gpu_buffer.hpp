// A Vulkan buffer with its own memory.
#pragma once

#include <cstddef>

#include <vulkan/vulkan_raii.hpp>

namespace lbmshape::gpu {

class GpuContext;

enum class MemoryUse {
  Device,    // fastest for the device; may not be visible to the host
  Upload,    // host-visible, written by the host
  Readback,  // host-visible, read by the host (cached where possible)
};

class GpuBuffer {
public:
  GpuBuffer(GpuContext& context, vk::DeviceSize bytes, vk::BufferUsageFlags usage, MemoryUse use);

  vk::Buffer handle() const { return *buffer_; }
  vk::DeviceSize bytes() const { return bytes_; }
  // Host pointer for Upload and Readback buffers (memory is host-coherent).
  std::byte* mapped() const { return mapped_; }

private:
  vk::DeviceSize bytes_;
  vk::raii::Buffer buffer_{nullptr};
  vk::raii::DeviceMemory memory_{nullptr};
  std::byte* mapped_ = nullptr;
};

}  // namespace lbmshape::gpu
