// The lattice's memory layout on the device (shaders/lattice_layout.glsl has
// the same formulas), and the checks that a lattice fits a device, made
// before anything is allocated so that an impossible grid is a usage error,
// not a driver crash.
#pragma once

#include <climits>

#include <array>
#include <cstdint>
#include <string>

#include "lbmshape/core/extent.hpp"
#include "lbmshape/gpu/device_description.hpp"
#include "lbmshape/lbm/d3q19.hpp"

namespace lbmshape {

// The nine groups of directions that pull from the same neighbouring row
// (e_y, e_z), numbered as ROW_GROUP in shaders/lattice_layout.glsl:
// (0,0) {0,1,2}, (1,0) {3,7,10}, (-1,0) {4,8,9}, (0,1) {5,11,14},
// (0,-1) {6,12,13}, then (1,1) {15}, (-1,-1) {16}, (1,-1) {17}, (-1,1) {18}.
// Each group is one contiguous array, so a step reads nine streams and
// writes nine.
namespace row_groups {
inline constexpr int count = 9;
inline constexpr int largest = 3;

constexpr int of(int ey, int ez)
{
  return ez == 0    ? (ey == 0   ? 0
                       : ey == 1 ? 1
                                 : 2)
         : ey == 0  ? (ez == 1 ? 3 : 4)
         : ey == ez ? (ey == 1 ? 5 : 6)
                    : (ey == 1 ? 7 : 8);
}
constexpr int size(int group) { return group < 5 ? 3 : 1; }
constexpr int start(int group) { return group < 5 ? 3 * group : 10 + group; }  // directions in the groups before

// Every group holds size() of the velocities, and the groups follow each other.
constexpr bool consistent()
{
  for (int g = 0; g < count; ++g) {
    int members = 0;
    for (const auto& v : d3q19::velocities) members += of(v.y, v.z) == g;
    if (members != size(g) || members > largest || start(g) != (g == 0 ? 0 : start(g - 1) + size(g - 1))) return false;
  }
  return start(count - 1) + size(count - 1) == d3q19::Q;
}
static_assert(consistent(), "row groups must match the D3Q19 velocities");
}  // namespace row_groups

// Cells are x-fastest with rows padded to `row` cells (a multiple of 4), and
// taken four at a time: block b holds cells 4b..4b+3 of that order.
//  - A lattice copy: for each row group g, the blocks one after another, each
//    with its size(g) directions side by side as vec4 (four cells).
//  - A volume (field, per-cell omega, source): one float per cell, the same
//    cell order.
struct LatticeLayout {
  Extent3 extent;
  int row = 0;
  uint64_t blocks = 0;       // four-cell blocks, rounded up to a multiple of 16 (group offsets stay 256-byte aligned)
  uint64_t copyBytes = 0;    // one lattice copy
  uint64_t volumeBytes = 0;  // one volume
  uint64_t totalBytes = 0;   // everything the Vulkan solver allocates

  uint64_t linearIndex(int x, int y, int z) const
  {
    return uint64_t(x) + uint64_t(row) * (uint64_t(y) + uint64_t(extent.ny) * uint64_t(z));
  }
  uint64_t groupOffsetBytes(int group) const { return uint64_t(row_groups::start(group)) * blocks * 16; }
  uint64_t groupBytes(int group) const { return uint64_t(row_groups::size(group)) * blocks * 16; }

  // Bytes moved per cell update: 19 distributions read and written, fp32.
  static constexpr uint64_t bytesPerUpdate = 19 * 4 * 2;
};

// Throws UsageError if a dimension is not positive.
void checkExtent(const Extent3& extent);

LatticeLayout latticeLayout(const Extent3& extent);

// Throws DeviceError naming the limit when the lattice does not fit the
// device, and the grid that would, its longest side at most `cap` (the
// host's, for a device that is the CPU: memory_sizes.hpp).
void checkFitsDevice(const LatticeLayout& layout, const gpu::DeviceDescription& device, int cap = INT32_MAX);

// The longest side checkFitsDevice names for a grid of `extent`'s proportions.
int latticeLongestSideThatFits(const Extent3& extent, const gpu::DeviceDescription& device);

}  // namespace lbmshape
