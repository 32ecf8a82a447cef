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
  layout.paddedCells = uint64_t(layout.row) * uint64_t(extent.ny) * uint64_t(extent.nz);
  // 256 bytes satisfies every device's binding offset alignment.
  layout.directionBytes = (layout.paddedCells * 4 + 255) / 256 * 256;
  const uint64_t fieldBytes = layout.paddedCells * 4;
  // two lattices, plus field, staging, per-cell omega and source
  layout.totalBytes = 2 * 19 * layout.directionBytes + 4 * fieldBytes;
  return layout;
}

void checkFitsDevice(const LatticeLayout& layout, const gpu::DeviceDescription& device)
{
  const Extent3& e = layout.extent;
  auto tooLarge = [&](const std::string& why) {
    throw UsageError("a " + e.toString() + " lattice does not fit on " + device.name + ": " + why +
                     "; use a coarser grid (--res) or another --device");
  };
  if (layout.paddedCells >= (uint64_t(1) << 31)) tooLarge("more than 2^31 cells");
  if (layout.directionBytes > device.maxStorageBufferRange)
    tooLarge("one direction needs " + mebibytes(layout.directionBytes) + " but a storage buffer may span at most " +
             mebibytes(device.maxStorageBufferRange));
  if (layout.paddedCells > device.maxTexelBufferElements)
    tooLarge(std::to_string(layout.paddedCells) + " cells exceed the texel buffer limit of " +
             std::to_string(device.maxTexelBufferElements) + " elements");
  if (uint64_t(e.ny) > device.maxWorkgroupCount[1] || uint64_t(e.nz) > device.maxWorkgroupCount[2])
    tooLarge("more rows than the device can dispatch");
  if (device.deviceLocalBytes && layout.totalBytes > device.deviceLocalBytes)
    tooLarge("it needs " + mebibytes(layout.totalBytes) + " but the device has " + mebibytes(device.deviceLocalBytes));
}

}  // namespace lbmshape
