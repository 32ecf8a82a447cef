// What a lattice of a given size needs on a device, checked before anything is
// allocated so that an impossible grid is a usage error, not a driver crash.
#pragma once

#include <cstdint>

#include "core/extent.hpp"
#include "gpu/device_description.hpp"

namespace lbmshape {

struct LatticeLayout {
  Extent3 extent;
  int row = 0;                  // padded row length: cells x0..x0+3 form one vec4
  uint64_t paddedCells = 0;     // row * ny * nz
  uint64_t directionBytes = 0;  // one direction's array, aligned for binding offsets
  uint64_t totalBytes = 0;      // everything the Vulkan solver allocates

  // Bytes moved per cell update: 19 distributions read and written, fp32.
  static constexpr uint64_t bytesPerUpdate = 19 * 4 * 2;
};

// Throws UsageError if a dimension is not positive.
void checkExtent(const Extent3& extent);

LatticeLayout latticeLayout(const Extent3& extent);

// Throws UsageError naming the limit when the lattice does not fit the device.
void checkFitsDevice(const LatticeLayout& layout, const gpu::DeviceDescription& device);

}  // namespace lbmshape
