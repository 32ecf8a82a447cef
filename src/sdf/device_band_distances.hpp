// Stage 1 of the band's signed distance on a Vulkan device
// (shaders/band_distance.comp): the exact unsigned distance of every stored
// cell, one invocation per cell walking a copy of the mesh's hierarchy. It
// replaces the CPU's exact band and far-field propagation
// (band_distance.hpp, far_field.hpp) where a GPU does the work faster than
// the host's cores; the sign stays on the CPU. Which one a run uses:
// ComputeDevice::bandDistances (pipeline/compute_device.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "lbmshape/sdf/grid_frame.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

namespace lbmshape {

namespace gpu {
class GpuContext;
}
class BandCells;

// Whether the device can hold the tree: its nodes and its triangles each
// within one storage-buffer binding (some 2 million triangles on lavapipe
// and on NVIDIA's drivers).
bool deviceHoldsTree(uint64_t maxStorageBufferRange, const TriangleBvh& bvh);

// Compiles the shader's pipeline (for a warm-up thread, ahead of the first call).
void prepareDeviceBandDistances(gpu::GpuContext& context);

// Per stored cell (BandCells numbering), its distance to the surface in
// voxels where that is at most maxVoxels (any value, +inf for all), +inf
// elsewhere and for the cells beyond the grid: the CPU's bandDistances()
// with every distance exact. Within float rounding of the CPU's exact
// distances (a few 1e-5 voxel); never above the true distance by more
// than the sign stage's margin (winding_sign.cpp, 1e-4 voxel).
// Interruptible between chunks of bricks (Interrupted, nothing written).
// DeviceError when the device cannot hold the tree (deviceHoldsTree).
// One caller at a time per context: the morph's two meshes, side by side,
// take turns (the caller's lock).
std::vector<float> deviceBandDistances(gpu::GpuContext& context, const TriangleBvh& bvh, const GridFrame& frame,
                                       const BandCells& cells, double maxVoxels);

}  // namespace lbmshape
