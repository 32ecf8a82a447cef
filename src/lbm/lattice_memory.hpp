// The lattice's memory layout on the device (shaders/lattice_layout.glsl has
// the same formulas), and the checks that a lattice fits a device, made
// before anything is allocated so that an impossible grid is a usage error,
// not a driver crash.
#pragma once

#include <cstdint>

#include "core/extent.hpp"
#include "gpu/device_description.hpp"

namespace lbmshape {

// Ghost rows and planes surround the grid in y and z; rows are padded to `row`
// cells (at least nx + 1, a multiple of 4); 4 floats lead and trail.
struct LatticeLayout {
  Extent3 extent;
  int row = 0;
  uint64_t plane = 0;               // row * (ny + 2)
  uint64_t floatsPerDirection = 0;  // 8 + plane * (nz + 2)
  uint64_t directionBytes = 0;      // aligned for any device's binding offsets
  uint64_t faceBlocks = 0;          // four-cell blocks on the largest y or z face
  uint64_t totalBytes = 0;          // everything the Vulkan solver allocates

  uint64_t linearIndex(int x, int y, int z) const
  {
    return uint64_t(4 + x + row * (y + 1)) + plane * uint64_t(z + 1);
  }

  // Bytes moved per cell update: 19 distributions read and written, fp32.
  static constexpr uint64_t bytesPerUpdate = 19 * 4 * 2;
};

// Throws UsageError if a dimension is not positive.
void checkExtent(const Extent3& extent);

LatticeLayout latticeLayout(const Extent3& extent);

// Throws UsageError naming the limit when the lattice does not fit the device.
void checkFitsDevice(const LatticeLayout& layout, const gpu::DeviceDescription& device);

}  // namespace lbmshape
