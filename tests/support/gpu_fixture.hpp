// One Vulkan context for the whole test binary (created on first use, with
// the Khronos validation layer on), and a fixture that fails any test during
// which the validation layer reported a warning or an error.
#pragma once

#include <gtest/gtest.h>

#include "lbmshape/gpu/gpu_context.hpp"

namespace lbmshape::testing {

gpu::GpuContext& sharedGpu();

class GpuTest : public ::testing::Test {
protected:
  void SetUp() override;
  void TearDown() override;
  gpu::GpuContext& gpu() { return sharedGpu(); }

private:
  int messagesBefore_ = 0;
};

}  // namespace lbmshape::testing
