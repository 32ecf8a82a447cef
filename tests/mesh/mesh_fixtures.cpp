#include "mesh/mesh_fixtures.hpp"

#include <algorithm>
#include <fstream>
#include <random>
#include <stdexcept>

#include <unistd.h>

namespace lbmshape::testing::meshio {

double signedVolume(const TriangleMesh& mesh)
{
  double volume = 0;
  for (const auto& t : mesh.triangles)
    volume += glm::dot(mesh.positions[t[0]], glm::cross(mesh.positions[t[1]], mesh.positions[t[2]])) / 6.0;
  return volume;
}

void writeText(const std::filesystem::path& path, const std::string& text)
{
  std::ofstream(path, std::ios::binary) << text;
}

void writeBytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes)
{
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

}  // namespace lbmshape::testing::meshio
