// Reading a surface mesh from a file, or from a file's bytes in memory, in
// any format lbmshape knows. Every reader treats its input as untrusted:
// whatever the bytes, the result is a mesh or an InputError, in time and
// memory bounded by the input's size.
#pragma once

#include <filesystem>

#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/mesh_source.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Reads an OBJ, PLY, OFF, STL, glTF or GLB file (chosen by extension, in any
// letter case) as a triangle soup: every face is kept, manifold or not, and
// polygons are fan-triangulated. The result is validated (see
// validateInputMesh): degenerate triangles are dropped, and anything that
// makes the file unusable (missing, not a regular file, unreadable, unknown
// extension, malformed, no triangles, a coordinate that is not finite, bad
// indices, no enclosed volume) is an InputError whose one-line message names
// the file. Normals are not read: lbmshape derives its own from the surface.
// With EmptyMesh::Allowed a file of no triangles (a morph's frame while
// the shape passes through nothing) is read as an empty mesh instead.
// With FlatMesh::Allowed a flat mesh (one plane, a single triangle) is read
// as it is.
TriangleMesh readMesh(const std::filesystem::path& path, EmptyMesh empty = EmptyMesh::Refused,
                      FlatMesh flat = FlatMesh::Refused);

// The same for bytes already in memory; `source.name` names them in messages.
TriangleMesh readMesh(const MeshSource& source, MeshFormat format, EmptyMesh empty = EmptyMesh::Refused,
                      FlatMesh flat = FlatMesh::Refused);

}  // namespace lbmshape
