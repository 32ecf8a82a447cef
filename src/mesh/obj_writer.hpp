// Wavefront OBJ files. Written here rather than by OpenMesh, whose writer
// rounds every coordinate to float: lbmshape keeps positions in double so
// that a mesh far from the origin keeps its detail, and an OBJ it writes
// reads back bit for bit.
#pragma once

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// `v` lines with each coordinate in the shortest text that reads back as the
// same double, `vn` lines when the mesh has normals, and `f` lines. Writes
// into file.temporaryPath(); throws OutputError naming file.target().
void writeObj(const TriangleMesh& mesh, const AtomicFile& file);

}  // namespace lbmshape
