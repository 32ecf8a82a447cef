// The test suite's promise that "any validation message fails the test" is
// only as good as the plumbing: prove that a real misuse is counted.
#include <gtest/gtest.h>

#include "lbmshape/gpu/gpu_context.hpp"

namespace lbmshape {
namespace {

TEST(ValidationLayer, CountsAMisuse)
{
  // Its own context, so the deliberate error stays out of the shared one.
  auto opened = gpu::GpuContext::open(gpu::GpuOptions{"", true});
  gpu::GpuContext& context = *opened;
  ASSERT_TRUE(context.validationEnabled());
  ASSERT_EQ(context.validationMessages(), 0);
  // A buffer of size 0 breaks VUID-VkBufferCreateInfo-size-00912.
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDevice device = *context.device();
  auto create = context.device().getDispatcher()->vkCreateBuffer;
  create(device, &info, nullptr, &buffer);
  EXPECT_GT(context.validationMessages(), 0);
  if (buffer != VK_NULL_HANDLE) context.device().getDispatcher()->vkDestroyBuffer(device, buffer, nullptr);
}

}  // namespace
}  // namespace lbmshape
