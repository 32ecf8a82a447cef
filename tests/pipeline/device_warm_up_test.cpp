// ComputeDevice::warmUpForTheBand: the device opened and the band's pipeline
// prepared on a thread of their own while a denoise computes its distances.
// It changes no result, and a device that cannot open fails where it did
// without it.
#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "lbmshape/pipeline/compute_device.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "support/band_fields.hpp"
#include "support/fields.hpp"
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

// The warm-up builds the pipelines of the kind of run it is told of (a
// morph's steps run with a source, --anisotropic's with the paper's rule,
// each a pipeline of its own: lavapipe takes some 100 ms a pipeline), so
// the run builds none of its own.
TEST(DeviceWarmUp, ARunBuildsNoPipelineItsWarmUpDidNot)
{
  const Extent3 extent{20, 20, 20};
  const Volume sphere = testing::sphereDistance(extent, 10.0, 10.0, 10.0, 6.0);
  const auto bricks = testing::bricksNear(sphere, 4.0);
  const BandRunKind kinds[] = {{}, {.source = true}, {.paperRule = true}};
  for (const BandRunKind& kind : kinds) {
    ComputeDevice device{"", true};
    device.warmUpForTheBand(kind);
    const size_t built = device.gpu()->programsBuilt();  // gpu() waits for the warm-up
    auto solver = device.makeBandSolver(bricks, kind);
    solver->setUniformGamma(0.2);
    if (kind.paperRule) solver->setPaperRule(0.2);
    if (kind.source) solver->setSource(BandSource{testing::bandOf(sphere, bricks), 0.1f});
    solver->initialize(testing::bandOf(sphere, bricks), 3.0);
    solver->step(3);
    const BandField field = solver->field();
    EXPECT_EQ(device.gpu()->programsBuilt(), built) << "source " << kind.source << ", paper's rule " << kind.paperRule;
  }
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
