// PLY, OFF and STL files, written by OpenMesh (coordinates in single
// precision, as those formats are normally read).
#pragma once

#include "core/atomic_file.hpp"
#include "mesh/mesh_format.hpp"
#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

// Writes into file.temporaryPath(): PLY and STL binary (little endian), OFF
// as text. Throws OutputError naming file.target().
void writeWithOpenMesh(const TriangleMesh& mesh, MeshFormat format, const AtomicFile& file);

}  // namespace lbmshape
