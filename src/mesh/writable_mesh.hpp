// What every writer needs of a mesh before it creates any file.
#pragma once

#include <filesystem>
#include <string>

#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

// Throws OutputError ("cannot write <path>: <what> has no triangles", a bad
// index, or a NaN/infinite coordinate): such a mesh would make an invalid file.
// `what` names the mesh in the message, e.g. "the mesh" or "frame 3".
void requireWritable(const TriangleMesh& mesh, const std::filesystem::path& path, const std::string& what = "the mesh");

}  // namespace lbmshape
