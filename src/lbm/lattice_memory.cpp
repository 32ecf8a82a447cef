#include "lbmshape/lbm/lattice_memory.hpp"

#include <algorithm>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/memory_sizes.hpp"

namespace lbmshape {

void checkExtent(const Extent3& e)
{
  if (e.nx <= 0 || e.ny <= 0 || e.nz <= 0)
    throw UsageError("grid size " + std::to_string(e.nx) + "," + std::to_string(e.ny) + "," + std::to_string(e.nz) +
                     " is invalid: every dimension must be at least 1");
}

LatticeLayout latticeLayout(const Extent3& extent)
{
  checkExtent(extent);
  LatticeLayout layout;
  layout.extent = extent;
  layout.row = (extent.nx + 3) / 4 * 4;
  const uint64_t cells = uint64_t(layout.row) * uint64_t(extent.ny) * uint64_t(extent.nz);
  layout.blocks = (cells / 4 + 15) / 16 * 16;
  layout.copyBytes = layout.blocks * d3q19::Q * 16;
  layout.volumeBytes = layout.blocks * 16;
  // two lattice copies, plus the field, staging, per-cell omega and source volumes
  layout.totalBytes = 2 * layout.copyBytes + 4 * layout.volumeBytes;
  return layout;
}

namespace {

// Why a lattice of `layout` does not fit on `device` ("" where it does).
std::string whyItDoesNotFit(const LatticeLayout& layout, const gpu::DeviceDescription& device)
{
  const Extent3& e = layout.extent;
  // The shaders index a lattice copy with 32-bit ints, in vec4 (and, in the
  // init pass, in floats within one group).
  const uint64_t copyTexels = layout.blocks * d3q19::Q;
  if (4 * layout.blocks * row_groups::largest >= (uint64_t(1) << 31) || copyTexels >= (uint64_t(1) << 31))
    return "more than " + std::to_string((uint64_t(1) << 31) / (4 * row_groups::largest)) + " cells";
  // The largest storage-buffer binding is a group of three directions (a
  // volume is a third of that).
  const uint64_t largestGroup = uint64_t(row_groups::largest) * layout.blocks * 16;
  if (largestGroup > device.maxStorageBufferRange)
    return "three directions need " + mebibytes(largestGroup) + " but a storage buffer may span at most " +
           mebibytes(device.maxStorageBufferRange);
  if (copyTexels > device.maxTexelBufferElements)
    return "the lattice needs " + std::to_string(copyTexels) + " texels but a texel buffer may hold at most " +
           std::to_string(device.maxTexelBufferElements);
  if (device.maxAllocationBytes && layout.copyBytes > device.maxAllocationBytes)
    return "the lattice needs " + mebibytes(layout.copyBytes) + " in one allocation, more than " +
           mebibytes(device.maxAllocationBytes);
  const uint64_t blocksPerPlane = uint64_t(layout.row / 4) * uint64_t(e.ny);
  if (blocksPerPlane / 128 + 1 > device.maxWorkgroupCount[0] || uint64_t(e.nz) > device.maxWorkgroupCount[2] ||
      uint64_t(layout.row) / 64 + 1 > device.maxWorkgroupCount[0] || uint64_t(e.ny) > device.maxWorkgroupCount[1])
    return "more workgroups than the device can dispatch";
  if (device.deviceLocalBytes && layout.totalBytes > device.deviceLocalBytes)
    return "it needs " + mebibytes(layout.totalBytes) + " but the device has " + mebibytes(device.deviceLocalBytes);
  return "";
}

// The longest side of the largest grid of `extent`'s proportions that fits.
int longestThatFits(const Extent3& extent, const gpu::DeviceDescription& device)
{
  const int longest = std::max({extent.nx, extent.ny, extent.nz});
  const auto scaled = [&](int side) {
    const auto by = [&](int n) { return std::max(1, int(int64_t(n) * side / longest)); };
    return Extent3{by(extent.nx), by(extent.ny), by(extent.nz)};
  };
  int fits = 0, fails = longest;  // fits may be 0: none does
  while (fails - fits > 1) {
    const int side = fits + (fails - fits) / 2;
    (whyItDoesNotFit(latticeLayout(scaled(side)), device).empty() ? fits : fails) = side;
  }
  return fits;
}

}  // namespace

int latticeLongestSideThatFits(const Extent3& extent, const gpu::DeviceDescription& device)
{
  // 3 % below the largest that fits in these proportions: a coarser --res
  // keeps the margins' voxels, so its shorter sides shrink a little less.
  return int(0.97 * longestThatFits(extent, device));
}

void checkFitsDevice(const LatticeLayout& layout, const gpu::DeviceDescription& device, int cap)
{
  const std::string why = whyItDoesNotFit(layout, device);
  if (why.empty()) return;
  const int fits = std::min(cap, latticeLongestSideThatFits(layout.extent, device));
  throw DeviceError("a " + layout.extent.toString() + " lattice does not fit on " + device.name + ": " + why + "; " +
                    (fits >= coarsestGrid
                         ? "a grid of about " + std::to_string(fits) + " cells along its longest side (" +
                               nameOf(Parameter::Resolution) + " " + std::to_string(fits) +
                               ") would fit, or use another " + nameOf(Parameter::Device)
                         : "no grid would fit (not even " + nameOf(Parameter::Resolution) + " " +
                               std::to_string(coarsestGrid) + "); use another " + nameOf(Parameter::Device)));
}

}  // namespace lbmshape
