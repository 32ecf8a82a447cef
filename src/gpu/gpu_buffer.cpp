#include "lbmshape/gpu/gpu_buffer.hpp"

#include "lbmshape/gpu/gpu_context.hpp"

namespace lbmshape::gpu {

GpuBuffer::GpuBuffer(GpuContext& context, vk::DeviceSize bytes, vk::BufferUsageFlags usage, MemoryUse use)
    : bytes_(bytes)
{
  auto& device = context.device();
  buffer_ = vk::raii::Buffer(device, vk::BufferCreateInfo({}, bytes, usage, vk::SharingMode::eExclusive));
  auto requirements = buffer_.getMemoryRequirements();
  using Flag = vk::MemoryPropertyFlagBits;
  vk::MemoryPropertyFlags required, preferred;
  switch (use) {
  case MemoryUse::Device: preferred = Flag::eDeviceLocal; break;
  case MemoryUse::Upload: required = Flag::eHostVisible | Flag::eHostCoherent; break;
  case MemoryUse::Readback:
    required = Flag::eHostVisible | Flag::eHostCoherent;
    preferred = Flag::eHostCached;
    break;
  case MemoryUse::DeviceReadByHost: preferred = Flag::eDeviceLocal; break;
  }
  const vk::MemoryPropertyFlags direct =
      Flag::eDeviceLocal | Flag::eHostVisible | Flag::eHostCoherent | Flag::eHostCached;
  uint32_t type = context.memoryType(requirements.memoryTypeBits, required, preferred);
  bool map = use == MemoryUse::Upload || use == MemoryUse::Readback;
  if (use == MemoryUse::DeviceReadByHost && !context.stagedReadback()) {
    const uint32_t readable = context.memoryType(requirements.memoryTypeBits, {}, direct);
    if ((context.memoryFlags(readable) & direct) == direct) type = readable, map = true;
  }
  memory_ = vk::raii::DeviceMemory(device, vk::MemoryAllocateInfo(requirements.size, type));
  buffer_.bindMemory(*memory_, 0);
  if (map) mapped_ = static_cast<std::byte*>(memory_.mapMemory(0, VK_WHOLE_SIZE));
}

}  // namespace lbmshape::gpu
