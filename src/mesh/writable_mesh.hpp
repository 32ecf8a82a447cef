// What every writer needs of a mesh before it creates any file.
#pragma once

#include <filesystem>
#include <string>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// How a format stores coordinates: OBJ as text, exactly; glTF as floats
// about a point it keeps in double (single_precision.hpp); PLY, STL and OFF
// (text of floats: OpenMesh's writer) as floats. A float coordinate beyond 3.4e38 would become infinite (a
// glTF's bounds null, a file no viewer shows).
enum class CoordinatePrecision { Double, SingleAboutAnOrigin, Single };

// Throws OutputError ("cannot write <path>: <what> has no triangles" unless
// `empty` allows it, a bad index, a NaN/infinite coordinate, one beyond
// single precision where the format stores that, or a mesh so far from the
// origin for its size that floats would move its vertices by more than a
// hundredth of its edges): such a mesh would make an invalid or a broken
// file. `what` names the mesh in the message, e.g. "the mesh" or "frame 3".
void requireWritable(const TriangleMesh& mesh, const std::filesystem::path& path, const std::string& what,
                     EmptyMesh empty, CoordinatePrecision precision);

}  // namespace lbmshape
