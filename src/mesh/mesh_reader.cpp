#include "mesh/mesh_reader.hpp"

#include <fstream>

#include "core/error.hpp"
#include "core/log.hpp"
#include "mesh/gltf_reader.hpp"
#include "mesh/mesh_format.hpp"
#include "mesh/mesh_validation.hpp"
#include "mesh/openmesh_reader.hpp"

namespace lbmshape {

TriangleMesh readMesh(const std::filesystem::path& path)
{
  const std::string prefix = "cannot read " + path.string() + ": ";
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw InputError(prefix + "no such file");
  if (std::filesystem::is_directory(status)) throw InputError(prefix + "it is a folder, not a file");
  if (!std::ifstream(path, std::ios::binary))
    throw InputError(prefix + "the file cannot be opened (check its permissions)");
  const auto format = meshFormatOf(path);
  if (!format)
    throw InputError(prefix + "unknown mesh format '" + path.extension().string() + "' (use one of " +
                     supportedExtensions() + ")");
  if (std::filesystem::file_size(path, ec) == 0) throw InputError(prefix + "the file is empty");

  TriangleMesh mesh = *format == MeshFormat::Gltf || *format == MeshFormat::Glb ? readGltf(path, *format)
                                                                                : readWithOpenMesh(path, *format);
  validateInputMesh(mesh, path);
  log::verbose("read " + path.string() + ": " + std::to_string(mesh.vertexCount()) + " vertices, " +
               std::to_string(mesh.triangleCount()) + " triangles");
  return mesh;
}

}  // namespace lbmshape
