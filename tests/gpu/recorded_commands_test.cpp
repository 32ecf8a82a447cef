// Steps are recorded once and replayed (gpu/recorded_commands.hpp): a replay
// runs the recorded commands again on whatever the buffers hold then, and a
// solver whose gamma, source or step count changes between calls gets the
// field a fresh recording gives, as the CPU reference computes it.
#include <algorithm>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "lbmshape/gpu/gpu_buffer.hpp"
#include "lbmshape/gpu/recorded_commands.hpp"
#include "lbmshape/lbm/band_reference_solver.hpp"
#include "lbmshape/lbm/band_vulkan_solver.hpp"
#include "lbmshape/lbm/reference_solver.hpp"
#include "lbmshape/lbm/vulkan_solver.hpp"
#include "support/band_fields.hpp"
#include "support/fields.hpp"
#include "support/gpu_fixture.hpp"

namespace lbmshape {
namespace {

class RecordedCommandsTest : public testing::GpuTest {};

TEST_F(RecordedCommandsTest, AReplayRunsTheCommandsAgainOnWhatTheBuffersHoldThen)
{
  const vk::DeviceSize bytes = 64 * sizeof(float);
  const auto usage = vk::BufferUsageFlagBits::eTransferSrc | vk::BufferUsageFlagBits::eTransferDst;
  using gpu::GpuBuffer, gpu::MemoryUse;
  GpuBuffer from(gpu(), bytes, usage, MemoryUse::Upload), to(gpu(), bytes, usage, MemoryUse::Readback);
  gpu::RecordedCommandCache cache;
  const std::string key = gpu::keyOf(1);
  auto copy = [&](vk::CommandBuffer cmd) {
    cmd.copyBuffer(from.handle(), to.handle(), vk::BufferCopy(0, 0, bytes));
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost, {},
                        vk::MemoryBarrier(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead), {}, {});
  };
  for (float value : {1.0f, 2.0f, 3.0f}) {
    std::vector<float> values(64, value);
    std::memcpy(from.mapped(), values.data(), bytes);
    gpu().replayAndWait(cache.get(gpu(), key, copy));
    std::vector<float> got(64);
    std::memcpy(got.data(), to.mapped(), bytes);
    EXPECT_EQ(got, values);
  }
  EXPECT_EQ(cache.recorded(), 1u) << "recorded once, replayed three times";
  cache.get(gpu(), gpu::keyOf(2), copy);
  EXPECT_EQ(cache.recorded(), 2u) << "another key, another recording";
}

TEST_F(RecordedCommandsTest, ACacheStartsOverBeyondItsCapacity)
{
  gpu::RecordedCommandCache cache(3);
  for (int k = 0; k < 5; ++k) cache.get(gpu(), gpu::keyOf(k), [](vk::CommandBuffer) {});
  EXPECT_LE(cache.size(), 3u);
  EXPECT_EQ(cache.recorded(), 5u);
}

// One step at a time (every batch replayed after the first two), with gamma
// changed half-way: the same field as the reference.
TEST_F(RecordedCommandsTest, GridStepsReplayedAcrossAGammaChangeMatchTheReference)
{
  const Extent3 extent{21, 17, 13};
  ReferenceSolver reference(extent);
  VulkanSolver vulkan(gpu(), extent);
  const Volume start = testing::randomField(extent, 0.5f, 1.5f, 3);
  for (LatticeSolver* s : std::initializer_list<LatticeSolver*>{&reference, &vulkan}) {
    s->setUniformGamma(0.2);
    s->initialize(start);
    for (int k = 0; k < 6; ++k) s->step(1);
    s->setUniformGamma(0.9);
    for (int k = 0; k < 6; ++k) s->step(1);
    s->step(3);
  }
  EXPECT_LT(testing::maxDifferenceForItsScale(vulkan.field(), reference.field()), testing::deviceTolerance);
  // A replay of the first gamma's steps would differ by far more.
  VulkanSolver stale(gpu(), extent);
  stale.setUniformGamma(0.2);
  stale.initialize(start);
  stale.step(15);
  EXPECT_GT(testing::maxDifferenceForItsScale(stale.field(), reference.field()), 100 * testing::deviceTolerance);
}

// Gamma per cell is another pipeline with the same push constants: the
// steps after it must not replay the uniform pipeline's recordings.
TEST_F(RecordedCommandsTest, GridStepsAfterASwitchToGammaPerCellMatchTheReference)
{
  const Extent3 extent{21, 17, 13};
  ReferenceSolver reference(extent);
  VulkanSolver vulkan(gpu(), extent);
  const Volume start = testing::randomField(extent, 0.5f, 1.5f, 3);
  const Volume gamma = testing::randomField(extent, 0.02f, 0.9f, 5);
  for (LatticeSolver* s : std::initializer_list<LatticeSolver*>{&reference, &vulkan}) {
    s->setUniformGamma(0.2);
    s->initialize(start);
    for (int k = 0; k < 4; ++k) s->step(1);
    s->setGammaPerCell(gamma);
    s->initialize(s->field());  // a restart, as --preserve-features makes
    for (int k = 0; k < 4; ++k) s->step(1);
  }
  EXPECT_LT(testing::maxDifferenceForItsScale(vulkan.field(), reference.field()), testing::deviceTolerance);
}

// The band, one step at a time, with its source's strength changed at every
// step as a morph's closing phase does: the same field as the reference.
TEST_F(RecordedCommandsTest, BandStepsReplayedAcrossSourceStrengthChangesMatchTheReference)
{
  const Extent3 extent{37, 29, 45};
  const Volume field = testing::sphereDistance(extent, 18.0, 14.5, 22.0, 17.0);
  auto bricks = testing::bricksNear(field, 8.0);
  const BandField target = testing::bandOf(testing::sphereDistance(extent, 20.0, 14.0, 20.0, 12.0), bricks);
  BandReferenceSolver reference(bricks);
  BandVulkanSolver vulkan(gpu(), bricks);
  for (BandSolver* s : std::initializer_list<BandSolver*>{&reference, &vulkan}) {
    s->setUniformGamma(0.15);
    s->setSource(BandSource{target, 0.1f, 0.1f});
    s->initialize(testing::bandOf(field, bricks), 6.0);
    for (int k = 0; k < 4; ++k) s->step(1);
    for (int k = 1; k <= 6; ++k) {
      s->setUniformGamma(0.15 / k);
      const float cs = 0.1f + 0.15f * float(k);
      s->setSourceStrength(cs, cs);
      s->step(1);
    }
  }
  const testing::BandDifference d = testing::differenceInside(vulkan.field(), reference.field(), extent);
  EXPECT_LE(d.worst, testing::deviceTolerance * d.scale) << "max |X|: " << d.scale;
  EXPECT_GT(d.scale, 1.0);
}

// Gamma per cell reallocates the band's omega buffer and writes its
// descriptor sets anew; the same gamma and a restart after it give the
// push constants of the first recordings, which must not be replayed (they
// bind the old sets: the validation layer fails the test if they are). A
// first source does the same.
TEST_F(RecordedCommandsTest, BandStepsAfterItsDescriptorsAreWrittenAgainMatchTheReference)
{
  const Extent3 extent{37, 29, 45};
  const Volume field = testing::sphereDistance(extent, 18.0, 14.5, 22.0, 17.0);
  auto bricks = testing::bricksNear(field, 8.0);
  BandField gamma = testing::bandOf(testing::randomField(extent, 0.02f, 0.6f, 5), bricks);
  for (float& g : gamma.values()) g = std::clamp(g, 0.02f, 0.6f);
  const BandField target = testing::bandOf(testing::sphereDistance(extent, 20.0, 14.0, 20.0, 12.0), bricks);
  BandReferenceSolver reference(bricks);
  BandVulkanSolver vulkan(gpu(), bricks);
  for (BandSolver* s : std::initializer_list<BandSolver*>{&reference, &vulkan}) {
    s->setUniformGamma(0.15);
    s->initialize(testing::bandOf(field, bricks), 6.0);
    for (int k = 0; k < 3; ++k) s->step(1);
    s->setGammaPerCell(gamma);
    s->setUniformGamma(0.15);
    s->initialize(s->field(), 6.0);
    for (int k = 0; k < 3; ++k) s->step(1);
    s->setSource(BandSource{target, 0.2f, 0.2f});
    s->initialize(s->field(), 6.0);
    for (int k = 0; k < 3; ++k) s->step(1);
  }
  const testing::BandDifference d = testing::differenceInside(vulkan.field(), reference.field(), extent);
  EXPECT_LE(d.worst, testing::deviceTolerance * d.scale) << "max |X|: " << d.scale;
  EXPECT_GT(d.scale, 1.0);
}

}  // namespace
}  // namespace lbmshape
