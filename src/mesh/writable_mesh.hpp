// What every writer needs of a mesh before it creates any file.
#pragma once

#include <filesystem>
#include <string>

#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

// How a format stores coordinates: OBJ as text, exactly; glTF, PLY, STL and
// OFF in single precision, where a coordinate beyond 3.4e38 would become
// infinite (a glTF's bounds null, a file no viewer shows).
enum class CoordinatePrecision { Double, Single };

// Throws OutputError ("cannot write <path>: <what> has no triangles" unless
// `empty` allows it, a bad index, a NaN/infinite coordinate, or one beyond
// single precision where the format stores that): such a mesh would make an
// invalid file. `what` names the mesh in the message, e.g. "the mesh" or
// "frame 3".
void requireWritable(const TriangleMesh& mesh, const std::filesystem::path& path, const std::string& what,
                     EmptyMesh empty, CoordinatePrecision precision);

}  // namespace lbmshape
