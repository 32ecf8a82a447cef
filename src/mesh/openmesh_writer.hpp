// PLY, OFF and STL files, written by OpenMesh (coordinates in single
// precision, as those formats are normally read).
#pragma once

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Writes into file.temporaryPath(): PLY and STL binary (little endian), OFF
// as text. Throws OutputError naming file.target().
void writeWithOpenMesh(const TriangleMesh& mesh, MeshFormat format, const AtomicFile& file);

}  // namespace lbmshape
