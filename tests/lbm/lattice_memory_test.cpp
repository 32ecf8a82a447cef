// The layout's sizes, and the checks that a lattice fits a device: each limit
// of the device, alone, turns an impossible grid into a usage error that names
// that limit (before anything is allocated).
#include <string>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/lbm/lattice_memory.hpp"
#include "support/roomy_device.hpp"

namespace lbmshape {
namespace {

using testing::roomyDevice;

std::string fitError(const Extent3& extent, const gpu::DeviceDescription& device)
{
  try {
    checkFitsDevice(latticeLayout(extent), device);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "";
}

TEST(LatticeLayout, SizesFollowTheRowGroups)
{
  const LatticeLayout l = latticeLayout({33, 40, 27});
  EXPECT_EQ(l.row, 36);                                     // padded to whole blocks of four cells
  EXPECT_EQ(l.blocks, (36u * 40 * 27 / 4 + 15) / 16 * 16);  // and to a multiple of 16 blocks
  EXPECT_EQ(l.copyBytes, l.blocks * 19 * 16);
  uint64_t next = 0;
  for (int g = 0; g < row_groups::count; ++g) {
    EXPECT_EQ(l.groupOffsetBytes(g), next) << "group " << g;
    EXPECT_EQ(l.groupOffsetBytes(g) % 256, 0u) << "every device accepts 256-byte binding offsets";
    next += l.groupBytes(g);
  }
  EXPECT_EQ(next, l.copyBytes);
}

TEST(LatticeFit, AGridThatFitsPasses) { EXPECT_EQ(fitError({128, 128, 128}, roomyDevice()), ""); }

TEST(LatticeFit, EachDeviceLimitIsNamed)
{
  const Extent3 grid{128, 128, 128};  // 2^21 cells: 152 MiB per lattice copy
  struct Limit {
    const char* what;
    void (*lower)(gpu::DeviceDescription&);
    const char* mentions;
  };
  const Limit limits[] = {
      {"memory", [](gpu::DeviceDescription& d) { d.deviceLocalBytes = 256u << 20; }, "the device has 256.0 MiB"},
      {"storage buffer range", [](gpu::DeviceDescription& d) { d.maxStorageBufferRange = 16u << 20; },
       "a storage buffer may span at most 16.0 MiB"},
      {"texel buffer", [](gpu::DeviceDescription& d) { d.maxTexelBufferElements = 1u << 20; },
       "a texel buffer may hold at most 1048576"},
      {"allocation", [](gpu::DeviceDescription& d) { d.maxAllocationBytes = 64u << 20; }, "in one allocation"},
      {"workgroups", [](gpu::DeviceDescription& d) { d.maxWorkgroupCount[2] = 64; }, "more workgroups"},
  };
  for (const Limit& limit : limits) {
    gpu::DeviceDescription device = roomyDevice();
    limit.lower(device);
    const std::string message = fitError(grid, device);
    EXPECT_NE(message.find(limit.mentions), std::string::npos) << limit.what << ": " << message;
    EXPECT_NE(message.find("128x128x128"), std::string::npos) << message;
  }
}

TEST(LatticeFit, MoreCellsThanThirtyTwoBitIndicesIsNamed)
{
  EXPECT_NE(fitError({2000, 2000, 2000}, roomyDevice()).find("cells"), std::string::npos);
}

// The refusal names a grid that fits: of each limit, a --res whose grid in
// the same proportions passes, and not far below the largest that does.
TEST(LatticeFit, ARefusalNamesAGridThatFits)
{
  const Extent3 grid{160, 192, 128};
  for (const auto lower : {+[](gpu::DeviceDescription& d) { d.deviceLocalBytes = 256u << 20; },
                           +[](gpu::DeviceDescription& d) { d.maxTexelBufferElements = 1u << 20; }}) {
    gpu::DeviceDescription device = roomyDevice();
    lower(device);
    const std::string message = fitError(grid, device);
    // "... along its longest side (<the resolution's name> N) would fit"
    const size_t close = message.find(") would fit");
    ASSERT_NE(close, std::string::npos) << message;
    const int res = std::stoi(message.substr(message.rfind(' ', close) + 1));
    ASSERT_GT(res, 8) << message;
    ASSERT_LT(res, 192) << message;
    const auto scaled = [&](int side) { return Extent3{160 * side / 192, side, 128 * side / 192}; };
    EXPECT_EQ(fitError(scaled(res), device), "") << message;
    EXPECT_NE(fitError(scaled(res * 11 / 10), device), "") << "within 10 % of the largest that fits: " << message;
  }
}

// A device too small for any grid: no --res is named (it named --res 0,
// itself refused).
TEST(LatticeFit, ADeviceTooSmallForAnyGridNamesNoResolution)
{
  gpu::DeviceDescription device = roomyDevice();
  device.deviceLocalBytes = 64u << 10;
  const std::string message = fitError({1024, 1024, 1024}, device);
  EXPECT_NE(message.find("no grid would fit (not even"), std::string::npos) << message;
  EXPECT_EQ(message.find(") would fit"), std::string::npos) << message;
}

TEST(LatticeFit, BadExtentIsAUsageError)
{
  EXPECT_THROW(latticeLayout({0, 8, 8}), UsageError);
  EXPECT_THROW(latticeLayout({8, -1, 8}), UsageError);
}

}  // namespace
}  // namespace lbmshape
