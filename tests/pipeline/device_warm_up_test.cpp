// ComputeDevice::warmUpForTheBand: the device opened and the band's pipeline
// prepared on a thread of their own while a denoise computes its distances.
// It changes no result, and a device that cannot open fails where it did
// without it.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "mesh/mesh_noise.hpp"
#include "pipeline/compute_device.hpp"
#include "pipeline/denoise.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

TEST(DeviceWarmUp, ADeviceThatCannotOpenFailsAtItsFirstUse)
{
  ComputeDevice device{"no device is called this", true};
  device.warmUpForTheBand({});  // fails on its thread, silently
  EXPECT_THROW(device.name(), UsageError);
  EXPECT_THROW(device.gpu(), UsageError);
}

TEST(DeviceWarmUp, ADeviceIsUsableAtOnceWhileItWarmsUp)
{
  ComputeDevice device{"", true};
  device.warmUpForTheBand({});
  EXPECT_FALSE(device.name().empty());  // the description, while the thread may still compile
  EXPECT_NE(device.gpu(), nullptr);     // waits for the thread
  EXPECT_GE(device.deviceBusyMs(), 0.0);
  ComputeDevice leaving{"", true};
  leaving.warmUpForTheBand({});  // goes while it warms up: its destructor waits for the thread
}

TEST(DeviceWarmUp, AWarmedUpDeviceDenoisesAsOneOpenedBefore)
{
  const TriangleMesh noisy = addNormalNoise(testing::icosphere(4), 0.3, 3);
  DenoiseOptions o;
  o.grid.resolution = 40;
  ComputeDevice warmed{"", true};  // the denoise warms it up while it computes distances
  ComputeDevice opened{"", true};
  opened.gpu();  // open already: no warm-up
  const DenoiseResult a = denoiseMesh(noisy, "a noisy sphere", o, warmed);
  const DenoiseResult b = denoiseMesh(noisy, "a noisy sphere", o, opened);
  ASSERT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  EXPECT_GT(a.mesh.triangleCount(), 0u);
  warmed.requireCleanValidation();
}

}  // namespace
}  // namespace lbmshape
