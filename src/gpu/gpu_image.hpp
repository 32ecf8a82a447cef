// A 2D Vulkan image with its own device memory and a view of it: the
// attachments the pictures are drawn into (render/).
#pragma once

#include <vulkan/vulkan_raii.hpp>

namespace lbmshape::gpu {

class GpuContext;

class GpuImage {
public:
  GpuImage(GpuContext& context, vk::Format format, vk::Extent2D extent, vk::SampleCountFlagBits samples,
           vk::ImageUsageFlags usage, vk::ImageAspectFlags aspect);

  vk::Image handle() const { return *image_; }
  vk::ImageView view() const { return *view_; }

private:
  vk::raii::Image image_{nullptr};
  vk::raii::DeviceMemory memory_{nullptr};
  vk::raii::ImageView view_{nullptr};
};

}  // namespace lbmshape::gpu
