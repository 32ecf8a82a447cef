#include "lbmshape/mesh/openmesh_writer.hpp"

#include <fstream>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>  // registers OpenMesh's writer modules

#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/openmesh_diagnostics.hpp"
#include "lbmshape/mesh/soup_exporter.hpp"

namespace lbmshape {

void writeWithOpenMesh(const TriangleMesh& mesh, MeshFormat format, const AtomicFile& file)
{
  const char* extension = format == MeshFormat::Ply ? "ply" : format == MeshFormat::Off ? "off" : "stl";
  OpenMesh::IO::Options options;
  if (format != MeshFormat::Off) options += OpenMesh::IO::Options::Binary;
  // Per-vertex normals in PLY: without them viewers shade every triangle
  // flat, and the smooth surface lbmshape made looks faceted.
  std::vector<glm::vec3> normals;
  if (format == MeshFormat::Ply) {
    options += OpenMesh::IO::Options::LSB;
    options += OpenMesh::IO::Options::VertexNormal;
    // A coloured mesh (a scan, --color curvature) keeps its colours.
    if (mesh.colours.size() == mesh.positions.size()) options += OpenMesh::IO::Options::VertexColor;
    if (mesh.normals.size() == mesh.positions.size()) {
      normals = mesh.normals;
    } else {
      for (const glm::dvec3& n : areaWeightedNormals(mesh)) normals.emplace_back(n);
    }
  }

  // Into our own stream rather than by file name: OpenMesh's writers do not
  // check that their output reached the disk, this stream does.
  std::ofstream out = file.open();
  SoupExporter exporter(mesh, std::move(normals));
  bool ok = false;
  std::string diagnostic;
  {
    OpenMeshDiagnostics diagnostics;
    // 9 significant digits: enough for any float to read back exactly (OFF
    // is text, of floats: OpenMesh's writer takes the float points).
    ok = out && OpenMesh::IO::IOManager().write(out, extension, exporter, options, 9);
    if (!ok) diagnostic = diagnostics.firstMessage();
  }
  out.close();
  if (!ok || !out)
    throw OutputError("cannot write " + file.target().string() + ": " +
                      (diagnostic.empty() ? writeFailure() : "OpenMesh: " + diagnostic));
}

}  // namespace lbmshape
