// OBJ, PLY, OFF and STL files, read by OpenMesh as a triangle soup.
#pragma once

#include <filesystem>

#include "mesh/mesh_format.hpp"
#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

// Every face of the file, polygons fan-triangulated; OBJ coordinates at full
// double precision, the others as the formats store them (float). Throws
// InputError when the file cannot be parsed or refers to missing vertices.
// No further checks: readMesh() validates.
TriangleMesh readWithOpenMesh(const std::filesystem::path& path, MeshFormat format);

}  // namespace lbmshape
