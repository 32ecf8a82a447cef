// For the mesh input/output tests: a box and a volume measure to go with
// the shared test meshes (support/test_meshes.hpp), and a scratch folder to
// write files into.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace lbmshape::testing::meshio {

// An axis-aligned closed box of 12 outward-facing triangles.
TriangleMesh box(glm::dvec3 min, glm::dvec3 max);

// sum over triangles of det(a, b, c) / 6: the enclosed volume, positive when
// the triangles face outwards.
double signedVolume(const TriangleMesh& mesh);

// A fresh empty folder under the system's temporary folder, removed with
// everything in it when the object goes.
class ScratchFolder {
public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Names of everything in the folder (hidden files too), sorted.
  std::vector<std::string> entries() const;

private:
  std::filesystem::path path_;
};

void writeText(const std::filesystem::path& path, const std::string& text);
void writeBytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes);

}  // namespace lbmshape::testing::meshio
