// Reading a surface mesh from a file, in any format lbmshape knows.
#pragma once

#include <filesystem>

#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

// Reads an OBJ, PLY, OFF, STL, glTF or GLB file (chosen by extension, in any
// letter case) as a triangle soup: every face is kept, manifold or not, and
// polygons are fan-triangulated. The result is validated (see
// validateInputMesh): degenerate triangles are dropped, and anything that
// makes the file unusable (missing, unreadable, unknown extension, no
// triangles, NaN, bad indices, no enclosed volume) is an InputError whose
// one-line message names the file. Normals are not read: lbmshape derives
// its own from the surface.
TriangleMesh readMesh(const std::filesystem::path& path);

}  // namespace lbmshape
