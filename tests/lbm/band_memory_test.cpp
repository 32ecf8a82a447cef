// The checks that a narrow band fits a device, made as soon as its bricks
// are known: each limit of the device, alone, lowers the cells a band may
// store, and a band beyond them is refused with what it needs and what grid
// would fit.
#include <cmath>

#include <gtest/gtest.h>

#include "lbmshape/band/brick_set.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/lbm/band_vulkan_solver.hpp"
#include "support/roomy_device.hpp"

namespace lbmshape {
namespace {

using testing::roomyDevice;

// A 64^3 grid with every brick active: 262144 stored cells.
BrickSet fullBricks()
{
  BrickSet bricks(Extent3{64, 64, 64});
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) bricks.activate(x, y, z);
  return bricks;
}

std::string refusal(const BrickSet& bricks, const gpu::DeviceDescription& device)
{
  try {
    BandVulkanSolver::checkFits(bricks, device, false, false);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "";
}

TEST(BandMemory, EachDeviceLimitBoundsTheCells)
{
  const uint64_t roomy = BandVulkanSolver::maxCells(roomyDevice(), false, false);
  EXPECT_GT(roomy, uint64_t(1) << 32);
  const uint64_t oneMiB = uint64_t(1) << 20;

  gpu::DeviceDescription d = roomyDevice();
  d.maxTexelBufferElements = 10 * oneMiB;  // the moments are one texel buffer
  EXPECT_EQ(BandVulkanSolver::maxCells(d, false, false), 10 * oneMiB);

  d = roomyDevice();
  d.maxAllocationBytes = 16 * oneMiB;  // a copy of the moments is 16 bytes a cell, in one allocation
  EXPECT_EQ(BandVulkanSolver::maxCells(d, false, false), oneMiB);

  d = roomyDevice();
  d.maxStorageBufferRange = 8 * oneMiB;  // 16 pools of 8 MiB of moments each
  EXPECT_EQ(BandVulkanSolver::maxCells(d, false, false), 16 * oneMiB / 2);

  d = roomyDevice();
  d.deviceLocalBytes = 1024 * oneMiB;
  const uint64_t plain = BandVulkanSolver::maxCells(d, false, false);
  const double perCell = BandVulkanSolver::deviceBytesPerCell(false, false);
  EXPECT_LE(double(plain) * perCell, double(d.deviceLocalBytes));
  EXPECT_GT(double(plain + brickCells) * perCell, double(d.deviceLocalBytes - BandVulkanSolver::defaultStagingBytes));
  EXPECT_LT(BandVulkanSolver::maxCells(d, true, true), plain) << "per-cell omega and a source take room too";
  EXPECT_EQ(plain % brickCells, 0u) << "whole bricks";
}

TEST(BandMemory, ABandBeyondTheDeviceIsRefusedWithWhatWouldFit)
{
  const BrickSet bricks = fullBricks();
  EXPECT_EQ(refusal(bricks, roomyDevice()), "");

  gpu::DeviceDescription small = roomyDevice();
  small.maxTexelBufferElements = 65536;  // a quarter of the band
  const std::string message = refusal(bricks, small);
  EXPECT_NE(message.find("262144 cells"), std::string::npos) << message;
  EXPECT_NE(message.find("test device holds at most 65536"), std::string::npos) << message;
  // Cells go as the area, the square of the side: half the side fits, less a margin.
  EXPECT_NE(message.find(nameOf(Parameter::Resolution) + " 30)"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace
}  // namespace lbmshape
