// Noisy copies of clean meshes, the test input of a denoiser.
#pragma once

#include <cstdint>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Moves every vertex along its area-weighted normal by a Gaussian amount of
// standard deviation sigmaInMeanEdgeLengths x meanEdgeLength(mesh); the
// vertices at one position (a soup's copies of a corner) move as one, along
// the normal of all their triangles, so the surface stays whole. The same
// seed gives the same mesh on every machine and compiler (the generator and
// the Gaussian are spelled out here, not left to the standard library). A
// vertex without a normal (no triangle with area uses it) stays put. The
// result has no normals: the old ones no longer fit. Throws UsageError for
// a sigma that is not a finite number of 0 or more, InputError for a mesh
// with an index out of range or a coordinate that is not finite.
TriangleMesh addNormalNoise(const TriangleMesh& mesh, double sigmaInMeanEdgeLengths, uint32_t seed);

}  // namespace lbmshape
