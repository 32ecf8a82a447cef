// PLY (ASCII and binary, either byte order), read by lbmshape itself (see
// ply_reader.cpp for why).
#pragma once

#include "lbmshape/mesh/mesh_source.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// The x, y and z of the "vertex" element (any numeric type) and the
// "vertex_indices" (or "vertex_index") list of the "face" element, polygons
// fan-triangulated; every other element and property is read past. Throws
// InputError saying where for a malformed header, a count the rest of the
// file cannot hold, a negative list length, an index outside the vertices, or
// a file that ends early.
TriangleMesh readPly(const MeshSource& source);

}  // namespace lbmshape
