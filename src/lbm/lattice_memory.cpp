#include "lbm/lattice_memory.hpp"

#include <algorithm>
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
  const auto [nx, ny, nz] = extent;
  layout.extent = extent;
  layout.row = (nx + 1 + 3) / 4 * 4;
  layout.plane = uint64_t(layout.row) * uint64_t(ny + 2);
  layout.floatsPerDirection = 8 + layout.plane * uint64_t(nz + 2);
  // 256 bytes satisfies every device's binding offset alignment.
  layout.directionBytes = (layout.floatsPerDirection * 4 + 255) / 256 * 256;
  layout.faceBlocks = uint64_t((nx + 3) / 4) * uint64_t(std::max(ny, nz));
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
  if (layout.floatsPerDirection >= (uint64_t(1) << 31)) tooLarge("more than 2^31 cells");
  if (layout.directionBytes > device.maxStorageBufferRange)
    tooLarge("one direction needs " + mebibytes(layout.directionBytes) + " but a storage buffer may span at most " +
             mebibytes(device.maxStorageBufferRange));
  if (layout.floatsPerDirection > device.maxTexelBufferElements)
    tooLarge(std::to_string(layout.floatsPerDirection) + " cells exceed the texel buffer limit of " +
             std::to_string(device.maxTexelBufferElements) + " elements");
  if (uint64_t(e.ny) + 2 > device.maxWorkgroupCount[1] || uint64_t(e.nz) + 2 > device.maxWorkgroupCount[2] ||
      std::max(layout.faceBlocks, 2 * uint64_t(e.ny) * e.nz) / 64 + 1 > device.maxWorkgroupCount[0])
    tooLarge("more workgroups than the device can dispatch");
  if (device.deviceLocalBytes && layout.totalBytes > device.deviceLocalBytes)
    tooLarge("it needs " + mebibytes(layout.totalBytes) + " but the device has " + mebibytes(device.deviceLocalBytes));
}

}  // namespace lbmshape
