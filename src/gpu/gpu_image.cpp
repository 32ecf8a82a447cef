#include "lbmshape/gpu/gpu_image.hpp"

#include "lbmshape/gpu/gpu_context.hpp"

namespace lbmshape::gpu {

GpuImage::GpuImage(GpuContext& context, vk::Format format, vk::Extent2D extent, vk::SampleCountFlagBits samples,
                   vk::ImageUsageFlags usage, vk::ImageAspectFlags aspect)
{
  auto& device = context.device();
  image_ = vk::raii::Image(device, vk::ImageCreateInfo({}, vk::ImageType::e2D, format, vk::Extent3D(extent, 1), 1, 1,
                                                       samples, vk::ImageTiling::eOptimal, usage,
                                                       vk::SharingMode::eExclusive, {}, vk::ImageLayout::eUndefined));
  const auto requirements = image_.getMemoryRequirements();
  const uint32_t type = context.memoryType(requirements.memoryTypeBits, {}, vk::MemoryPropertyFlagBits::eDeviceLocal);
  memory_ = vk::raii::DeviceMemory(device, vk::MemoryAllocateInfo(requirements.size, type));
  image_.bindMemory(*memory_, 0);
  view_ = vk::raii::ImageView(device, vk::ImageViewCreateInfo({}, *image_, vk::ImageViewType::e2D, format, {},
                                                              vk::ImageSubresourceRange(aspect, 0, 1, 0, 1)));
}

}  // namespace lbmshape::gpu
