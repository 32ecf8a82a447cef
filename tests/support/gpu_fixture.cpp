#include "support/gpu_fixture.hpp"

#include <memory>

namespace lbmshape::testing {

namespace {

std::unique_ptr<gpu::GpuContext>& sharedSlot()
{
  static std::unique_ptr<gpu::GpuContext> context;
  return context;
}

// After the last test, destroys the shared context while its instance still
// counts what the validation layer says: a leaked object is reported only
// when the device goes, after every test's own check.
class SharedGpuTeardown : public ::testing::Environment {
public:
  void TearDown() override
  {
    if (!sharedSlot()) return;
    std::shared_ptr<gpu::VulkanInstance> instance = sharedSlot()->instance();
    const int before = instance->validationMessages();
    sharedSlot().reset();
    EXPECT_EQ(instance->validationMessages(), before)
        << "the Vulkan validation layer reported problems while the device was destroyed (see stderr)";
  }
};

const ::testing::Environment* const teardown = ::testing::AddGlobalTestEnvironment(new SharedGpuTeardown);

}  // namespace

gpu::GpuContext& sharedGpu()
{
  if (!sharedSlot()) {
    gpu::GpuOptions options;
    options.validation = true;
    sharedSlot() = gpu::GpuContext::open(options);
  }
  return *sharedSlot();
}

void GpuTest::SetUp()
{
  ASSERT_TRUE(gpu().validationEnabled()) << "GPU tests must run with the Khronos validation layer";
  messagesBefore_ = gpu().validationMessages();
}

void GpuTest::TearDown()
{
  EXPECT_EQ(gpu().validationMessages(), messagesBefore_)
      << "the Vulkan validation layer reported problems (see stderr)";
}

}  // namespace lbmshape::testing
