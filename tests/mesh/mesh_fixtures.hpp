// For the mesh input/output tests: a volume measure to go with the shared
// test meshes (support/test_meshes.hpp, which also has the box), and a
// scratch folder to write files into.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lbmshape/mesh/triangle_mesh.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape::testing::meshio {

// sum over triangles of det(a, b, c) / 6: the enclosed volume, positive when
// the triangles face outwards.
double signedVolume(const TriangleMesh& mesh);

void writeText(const std::filesystem::path& path, const std::string& text);
void writeBytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes);

}  // namespace lbmshape::testing::meshio
