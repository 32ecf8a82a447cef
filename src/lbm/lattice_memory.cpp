#include "lbm/lattice_memory.hpp"

#include <sstream>

#include "core/error.hpp"

namespace lbmshape {
namespace {
std::string mebibytes(uint64_t bytes)
{
  std::ostringstream s;
  s.precision(1);
  s << std::fixed << double(bytes) / (1024.0 * 1024.0) << " MiB";
  return s.str();
}
}  // namespace

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
  // 64 floats = 256 bytes satisfies every device's binding offset alignment.
  layout.directionFloats = (uint64_t(layout.row) * uint64_t(extent.ny) * uint64_t(extent.nz) + 63) / 64 * 64;
  layout.directionBytes = layout.directionFloats * 4;
  // two lattices, plus the field, staging, per-cell omega and source volumes
  layout.totalBytes = (2 * 19 + 4) * layout.directionBytes;
  return layout;
}

void checkFitsDevice(const LatticeLayout& layout, const gpu::DeviceDescription& device)
{
  const Extent3& e = layout.extent;
  auto tooLarge = [&](const std::string& why) {
    throw UsageError("a " + e.toString() + " lattice does not fit on " + device.name + ": " + why +
                     "; use a coarser grid (--res) or another --device");
  };
  const uint64_t pairFloats = 2 * layout.directionFloats;
  if (pairFloats >= (uint64_t(1) << 31)) tooLarge("more than 2^30 cells");
  if (layout.directionBytes > device.maxStorageBufferRange)
    tooLarge("one direction needs " + mebibytes(layout.directionBytes) + " but a storage buffer may span at most " +
             mebibytes(device.maxStorageBufferRange));
  if (pairFloats > device.maxTexelBufferElements)
    tooLarge("two directions need " + std::to_string(pairFloats) + " texels but a texel buffer may hold at most " +
             std::to_string(device.maxTexelBufferElements));
  if (device.maxAllocationBytes && 2 * layout.directionBytes > device.maxAllocationBytes)
    tooLarge("two directions need " + mebibytes(2 * layout.directionBytes) + " in one allocation, more than " +
             mebibytes(device.maxAllocationBytes));
  const uint64_t blocksPerPlane = uint64_t(layout.row / 4) * uint64_t(e.ny);
  if (blocksPerPlane / 128 + 1 > device.maxWorkgroupCount[0] || uint64_t(e.nz) > device.maxWorkgroupCount[2] ||
      uint64_t(layout.row) / 64 + 1 > device.maxWorkgroupCount[0] || uint64_t(e.ny) > device.maxWorkgroupCount[1])
    tooLarge("more workgroups than the device can dispatch");
  if (device.deviceLocalBytes && layout.totalBytes > device.deviceLocalBytes)
    tooLarge("it needs " + mebibytes(layout.totalBytes) + " but the device has " + mebibytes(device.deviceLocalBytes));
}

}  // namespace lbmshape
