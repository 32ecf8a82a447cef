#include "mesh/openmesh_reader.hpp"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>  // registers OpenMesh's reader modules

#include "core/error.hpp"
#include "core/log.hpp"
#include "mesh/obj_positions.hpp"
#include "mesh/openmesh_diagnostics.hpp"
#include "mesh/soup_importer.hpp"

namespace lbmshape {

TriangleMesh readWithOpenMesh(const std::filesystem::path& path, MeshFormat format)
{
  const std::string prefix = "cannot read " + path.string() + ": ";
  SoupImporter importer;
  bool ok = false;
  std::string diagnostic;
  {
    OpenMeshDiagnostics diagnostics;
    OpenMesh::IO::Options options;  // positions and faces only
    ok = OpenMesh::IO::IOManager().read(path.string(), importer, options);
    if (!ok) diagnostic = diagnostics.firstMessage();
  }
  if (!ok)
    throw InputError(prefix + "not a readable " + formatName(format) + " file" +
                     (diagnostic.empty() ? std::string() : " (OpenMesh: " + diagnostic + ")"));
  // A malformed OBJ vertex line shifts later indices, so it is the cause to
  // report even when a face index is what went out of range.
  ObjPositions exact;
  if (format == MeshFormat::Obj) {
    exact = readObjPositions(path);
    if (exact.problem) throw InputError(prefix + *exact.problem);
  }
  if (importer.badIndex()) throw InputError(prefix + *importer.badIndex());
  if (size_t n = importer.facesWithTooFewVertices())
    log::verbose(path.string() + ": skipped " + std::to_string(n) + " faces with fewer than 3 vertices");

  TriangleMesh mesh = importer.takeMesh();
  if (mesh.positions.empty() && mesh.triangles.empty())
    throw InputError(prefix + "no vertices or faces found (is it really in " + formatName(format) + " format?)");
  if (format == MeshFormat::Obj) {
    if (exact.positions.size() != mesh.positions.size())
      throw InputError(prefix + "found " + std::to_string(exact.positions.size()) +
                       " vertex lines but could parse only " + std::to_string(mesh.positions.size()));
    mesh.positions = std::move(exact.positions);
  }
  return mesh;
}

}  // namespace lbmshape
