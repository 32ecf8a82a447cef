#include "lbmshape/mesh/mesh_reader.hpp"

#include "lbmshape/core/log.hpp"
#include "lbmshape/core/mapped_file.hpp"
#include "lbmshape/mesh/compressed_file.hpp"
#include "lbmshape/mesh/gltf_reader.hpp"
#include "lbmshape/mesh/mesh_validation.hpp"
#include "lbmshape/mesh/obj_reader.hpp"
#include "lbmshape/mesh/off_reader.hpp"
#include "lbmshape/mesh/ply_reader.hpp"
#include "lbmshape/mesh/stl_reader.hpp"

namespace lbmshape {

TriangleMesh readMesh(const MeshSource& source, MeshFormat format, EmptyMesh empty, FlatMesh flat)
{
  if (source.bytes.empty()) source.refuse("the file is empty");
  // A binary STL's 80-byte header is free text: a compressed STL is told
  // from a binary one by its size (stl_reader.cpp).
  if (format != MeshFormat::Stl) refuseCompressed(source);
  TriangleMesh mesh;
  switch (format) {
  case MeshFormat::Obj: mesh = readObj(source); break;
  case MeshFormat::Ply: mesh = readPly(source); break;
  case MeshFormat::Off: mesh = readOff(source); break;
  case MeshFormat::Stl: mesh = readStl(source); break;
  case MeshFormat::Gltf:
  case MeshFormat::Glb: mesh = readGltf(source, format); break;
  }
  if (mesh.triangles.empty() && empty == EmptyMesh::Allowed) {
    mesh.positions.clear();  // nothing to check, nothing to draw
    return mesh;
  }
  validateInputMesh(mesh, source.name, flat);
  log::verbose("read " + source.name + ": " + std::to_string(mesh.vertexCount()) + " vertices, " +
               std::to_string(mesh.triangleCount()) + " triangles");
  return mesh;
}

TriangleMesh readMesh(const std::filesystem::path& path, EmptyMesh empty, FlatMesh flat)
{
  const std::string name = path.string();
  const auto format = meshFormatOf(path);
  // The file is opened first: a missing file is reported as missing, whatever its name.
  const MappedFile file(path);
  if (!format)
    throw InputError("cannot read " + name + ": unknown mesh format '" + path.extension().string() + "' (use one of " +
                     supportedExtensions() + ")");
  return readMesh(MeshSource{file.bytes(), name, path.parent_path()}, *format, empty, flat);
}

}  // namespace lbmshape
