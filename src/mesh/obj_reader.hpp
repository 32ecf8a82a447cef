// Wavefront OBJ, read by lbmshape itself (see obj_reader.cpp for why).
#pragma once

#include "lbmshape/mesh/mesh_source.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Every `v` line (x y z at full double precision; a w or colour after them
// is ignored) and every `f` line (polygons fan-triangulated; indices 1-based
// or negative, i.e. relative to the vertices before the line; v, v/vt, v//vn
// and v/vt/vn corners). Other statements (vt, vn, g, o, s, l, p, usemtl, ...)
// are ignored; faces with fewer than three corners are skipped with a
// warning. Throws InputError naming the line for anything else: a vertex
// without three finite coordinates, a corner without a vertex index, an
// index of 0 or beyond the vertices.
TriangleMesh readObj(const MeshSource& source);

}  // namespace lbmshape
