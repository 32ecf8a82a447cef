#include "support/gpu_fixture.hpp"

#include <memory>

namespace lbmshape::testing {

gpu::GpuContext& sharedGpu()
{
  static std::unique_ptr<gpu::GpuContext> context = [] {
    gpu::GpuOptions options;
    options.validation = true;
    return gpu::GpuContext::open(options);
  }();
  return *context;
}

void GpuTest::SetUp()
{
  ASSERT_TRUE(gpu().validationEnabled()) << "GPU tests must run with the Khronos validation layer";
  messagesBefore_ = gpu().validationMessages();
}

void GpuTest::TearDown()
{
  EXPECT_EQ(gpu().validationMessages(), messagesBefore_) << "the Vulkan validation layer reported problems (see stderr)";
}

}  // namespace lbmshape::testing
