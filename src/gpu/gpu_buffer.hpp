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
  // Device, and mapped for the host where the device's own memory is also
  // host-visible and cached (a CPU device like lavapipe; integrated GPUs):
  // results are read there without a copy into a staging buffer. Elsewhere
  // (a discrete GPU, whose host-visible device memory is uncached across
  // the bus) exactly Device: not mapped.
  DeviceReadByHost,
};

class GpuBuffer {
public:
  GpuBuffer(GpuContext& context, vk::DeviceSize bytes, vk::BufferUsageFlags usage, MemoryUse use);

  vk::Buffer handle() const { return *buffer_; }
  vk::DeviceSize bytes() const { return bytes_; }
  // Host pointer for Upload and Readback buffers, and DeviceReadByHost ones
  // where the device allows (memory is host-coherent); else null.
  std::byte* mapped() const { return mapped_; }

private:
  vk::DeviceSize bytes_;
  vk::raii::Buffer buffer_{nullptr};
  vk::raii::DeviceMemory memory_{nullptr};
  std::byte* mapped_ = nullptr;
};

}  // namespace lbmshape::gpu
