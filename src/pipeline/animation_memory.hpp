// A morph's preview, and a compressed morph.glb, hold every frame until the
// last one is done, which at a fine grid and many frames is more than the
// lattice (a plain morph.glb is streamed to its file and holds none). This
// estimates it from the shapes before any work, and refuses a morph whose
// frames cannot fit, saying how many would.
#pragma once

#include <cstdint>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Marching cubes cuts a surface into about this many triangles per voxel^2
// of its area (tests/pipeline/animation_memory_test.cpp measures it on a
// sphere and a torus).
inline constexpr double trianglesPerVoxelArea = 3.0;
// Per triangle of every frame: the glTF buffers (positions, normals,
// indices: about 24 B), in one array that grows by doubling, so up to three
// times that while it moves; measured as the peak RSS of a morph with the
// animation less that of one without, over the triangles of all its frames
// (docs/morphing.md): 33 B at --res 128, 48 frames (57 B when every frame's
// mesh was kept as well, before the animation was assembled alongside).
inline constexpr double animationBytesPerTriangle = 60.0;

// Host bytes of an animation of `frames` frames of a surface of
// `areaInVoxels` (voxel side = 1): the frames' meshes and morph.glb's
// buffers while it is assembled.
double animationBytes(double areaInVoxels, int frames);

// What holds every frame's mesh or arrays in memory until the end: the
// preview's pictures, or a compressed morph.glb (a plain one is streamed to
// its file as the frames come).
enum class FramesHeldBy { Preview, CompressedAnimation };

// Throws DeviceError (exit 5) when animationBytes for the larger of the two
// shapes' areas, at this voxel size, exceeds what the host allows: "the N
// frames of the preview (of a compressed morph.glb) need about X MiB but
// this machine allows Y MiB; about K frames would fit, or leave out
// --preview (--compress ...)".
void checkAnimationFits(const TriangleMesh& source, const TriangleMesh& target, double voxel, int frames,
                        FramesHeldBy heldBy);

}  // namespace lbmshape
