// The checks every mesh passes on its way in, whatever its format: what
// makes a file unusable is an InputError naming the file; what only makes it
// untidy is fixed quietly.
#pragma once

#include <string>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Throws InputError ("cannot read <name>: <what is wrong>") when the mesh has
// no triangles, an index out of range, a coordinate that is NaN, infinite or
// beyond single precision (every format but OBJ stores float), only
// degenerate (zero-area) triangles, or encloses no volume because all of it
// lies in one plane (which includes a single triangle). Otherwise removes the
// degenerate triangles and those that repeat an earlier one's corners in the
// same turn (a warning says how many of each) and returns. Vertices no
// triangle uses are allowed and kept. With FlatMesh::Allowed a flat mesh
// passes.
void validateInputMesh(TriangleMesh& mesh, const std::string& name, FlatMesh flat = FlatMesh::Refused);

// Its first checks alone, which change nothing: every index in range and
// every coordinate finite and within single precision (what a function
// that indexes positions needs before it reads them).
void requireWellFormed(const TriangleMesh& mesh, const std::string& name);

}  // namespace lbmshape
