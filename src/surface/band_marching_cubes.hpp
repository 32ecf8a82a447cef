// Marching cubes over the narrow band: the surface X = iso of a field stored
// on active bricks only. Every cube whose corners straddle the isovalue is
// triangulated by the same case table, with the same vertex placement and
// normals, as extractSurface() does on a whole grid, so where the band holds
// the surface the two meshes are the same (up to the order of vertices and
// triangles); the closed-manifold guarantee carries over whenever every cube
// the surface passes through has its eight corners in the band, which the
// band's half width (at least 2 voxels beyond the surface) provides.
#pragma once

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape {

// Vertices and triangles in the order of the bricks (their slots) and of the
// cubes in them, so the result does not depend on the number of threads.
// Throws std::invalid_argument when the frame's extent differs from the
// field's, NumericalError when a stored sample is NaN or infinite.
TriangleMesh extractSurface(const BandField& field, const GridFrame& frame, float isovalue = 0.0f);

}  // namespace lbmshape
