// The lattice's memory layout on the device (shaders/lattice_layout.glsl has
// the same formulas), and the checks that a lattice fits a device, made
// before anything is allocated so that an impossible grid is a usage error,
// not a driver crash.
#pragma once

#include <cstdint>

#include "core/extent.hpp"
#include "gpu/device_description.hpp"

namespace lbmshape {

// Rows are padded to `row` cells (a multiple of 4); each direction's array
// takes `directionFloats`; opposite directions share one buffer ("pair").
struct LatticeLayout {
  Extent3 extent;
  int row = 0;
  uint64_t directionFloats = 0;  // row * ny * nz, rounded up so offsets stay 256-byte aligned
  uint64_t directionBytes = 0;
  uint64_t totalBytes = 0;       // everything the Vulkan solver allocates

  static constexpr int pairs = 10;  // the rest direction, then (1,2), (3,4), ... (17,18)

  uint64_t linearIndex(int x, int y, int z) const { return uint64_t(x) + uint64_t(row) * (uint64_t(y) + uint64_t(extent.ny) * uint64_t(z)); }
  static int pairOf(int direction) { return (direction + 1) / 2; }
  // Offset of a direction's array in its pair buffer, in floats.
  uint64_t offsetInPair(int direction) const { return direction > 0 && direction % 2 == 0 ? directionFloats : 0; }
  uint64_t pairBytes(int pair) const { return pair == 0 ? directionBytes : 2 * directionBytes; }

  // Bytes moved per cell update: 19 distributions read and written, fp32.
  static constexpr uint64_t bytesPerUpdate = 19 * 4 * 2;
};

// Throws UsageError if a dimension is not positive.
void checkExtent(const Extent3& extent);

LatticeLayout latticeLayout(const Extent3& extent);

// Throws UsageError naming the limit when the lattice does not fit the device.
void checkFitsDevice(const LatticeLayout& layout, const gpu::DeviceDescription& device);

}  // namespace lbmshape
