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

// A plain morph.glb streams its frames to the file, which glTF's binary
// container caps at 4 GiB (its length is 32 bits): it failed only once it
// got there (--frames 100000 at --res 48: two minutes, 20,863 frames
// written). Throws OutputError (exit 4), before any work, where even the
// smaller of the two shapes' surfaces, at this voxel size, gives a file past
// that: "morph.glb's N frames would take about X GiB, past the 4 GiB a .glb
// holds; about K frames would fit, ...". Plain morph.glb frames take about
// 24 B a triangle (positions, normals, indices: 24.2 measured).
inline constexpr double glbBytesPerTriangle = 24.0;
void checkAnimationFileFits(const TriangleMesh& source, const TriangleMesh& target, double voxel, int frames);

// Throws DeviceError (exit 5) when animationBytes for the larger of the two
// shapes' areas, at this voxel size, exceeds what the host allows: "the N
// frames of the preview (of a compressed morph.glb) need about X MiB but
// this machine allows Y MiB; about K frames would fit, or leave out
// --preview (--compress ...)".
void checkAnimationFits(const TriangleMesh& source, const TriangleMesh& target, double voxel, int frames,
                        FramesHeldBy heldBy);

}  // namespace lbmshape
