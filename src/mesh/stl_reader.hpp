// STL, binary or ASCII, read by lbmshape itself (see stl_reader.cpp for why).
#pragma once

#include "lbmshape/mesh/mesh_source.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Binary STL when the file's size is exactly what its triangle count needs
// (84 + 50 bytes a triangle), whatever its header says; otherwise ASCII when
// it begins with "solid". STL stores every triangle's corners apart: equal
// positions are merged into one vertex, numbered in the order they are
// first met. ASCII is read as strictly as OBJ: a vertex without three finite
// coordinates, a facet without exactly three vertices, or a file that ends
// inside a solid is an InputError naming the line.
TriangleMesh readStl(const MeshSource& source);

}  // namespace lbmshape
