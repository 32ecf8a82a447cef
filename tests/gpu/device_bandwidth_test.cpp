// bench's bandwidth on a GPU: the compute-shader scale over device-local
// arrays (shaders/bandwidth_scale.comp). Lavapipe's bench measures the host's
// memory instead, so this runs the GPU path on it directly, with the
// validation layer watching its barriers.
#include <gtest/gtest.h>

#include <cmath>

#include "lbmshape/bench/memory_bandwidth.hpp"
#include "support/gpu_fixture.hpp"

namespace lbmshape {
namespace {

class DeviceBandwidth : public testing::GpuTest {};

TEST_F(DeviceBandwidth, TheComputeShaderScaleGivesAFiniteFigureAndSaysHow)
{
  const BandwidthMeasurement m = measureDeviceBandwidth(gpu(), 4u << 20, 0.0);
  EXPECT_TRUE(std::isfinite(m.gbps)) << m.gbps;
  EXPECT_GT(m.gbps, 0.0);
  EXPECT_NE(m.method.find("compute-shader scale"), std::string::npos) << m.method;
  EXPECT_NE(m.method.find("4 MiB arrays"), std::string::npos) << m.method;
}

TEST_F(DeviceBandwidth, ArraysBeyondTheStorageBufferRangeAreCutToIt)
{
  const uint64_t range = gpu().limits().maxStorageBufferRange;
  if (range >= (uint64_t(1) << 32) - 1) GTEST_SKIP() << "this device's storage buffers reach 4 GiB";
  const BandwidthMeasurement m = measureDeviceBandwidth(gpu(), range + (64u << 20), 0.0);
  EXPECT_GT(m.gbps, 0.0);
  EXPECT_NE(m.method.find(std::to_string((range / 16 * 16) >> 20) + " MiB arrays"), std::string::npos) << m.method;
}

}  // namespace
}  // namespace lbmshape
