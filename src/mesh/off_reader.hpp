// OFF (Geomview's Object File Format), ASCII or binary, read by lbmshape
// itself (see off_reader.cpp for why).
#pragma once

#include "lbmshape/mesh/mesh_source.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// "[ST][C][N]OFF" headers (or none: the counts first), "V F E" counts, one
// vertex per line (x y z, then whatever the header announced, ignored), one
// face per line ("n i1 ... in", then an optional colour, ignored), polygons
// fan-triangulated; "#" starts a comment. "OFF BINARY" reads Geomview's
// big-endian binary body. Throws InputError naming the line for counts the
// file cannot hold, a vertex without three finite coordinates, a face with
// fewer indices than it announces, an index outside the vertices, or a file
// that ends early; 4OFF and nOFF (other dimensions) are refused.
TriangleMesh readOff(const MeshSource& source);

}  // namespace lbmshape
