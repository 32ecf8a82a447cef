#include "lbmshape/pipeline/input_orientation.hpp"

#include <utility>
#include <vector>

#include "lbmshape/core/log.hpp"
#include "lbmshape/mesh/vertex_welding.hpp"
#include "lbmshape/sdf/shell_orientation.hpp"

namespace lbmshape {
namespace {

// The mesh with corners at equal positions made one vertex (a triangle
// soup; a glTF split at its UV seams and sharp edges, as Blender exports
// it), each vertex keeping the normal and colour of a corner there: the
// pieces the file's numbering cut apart are one surface again, which can be
// closed, face out as a whole and keep its volume.
TriangleMesh welded(const TriangleMesh& mesh)
{
  std::vector<glm::dvec3> corners;
  corners.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) corners.push_back(mesh.positions[t[k]]);
  TriangleMesh joined = weldEqualPositions(corners);
  const auto carry = [&](const auto& perVertex, auto& into) {
    if (perVertex.size() != mesh.positions.size()) return;
    into.resize(joined.positions.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) into[joined.triangles[t][k]] = perVertex[mesh.triangles[t][k]];
  };
  carry(mesh.normals, joined.normals);
  carry(mesh.colours, joined.colours);
  return joined;
}

}  // namespace

MeshTopology orientTheInput(TriangleMesh& mesh, const std::string& name)
{
  MeshTopology topology = analyzeTopology(mesh);
  if (topology.boundaryEdges > 0) {
    TriangleMesh joined = welded(mesh);
    MeshTopology joinedTopology = analyzeTopology(joined);
    if (joinedTopology.boundaryEdges < topology.boundaryEdges) {
      log::verbose(name + ": " + std::to_string(mesh.vertexCount() - joined.vertexCount()) +
                   " vertices at the positions of others joined to them (" + std::to_string(topology.boundaryEdges) +
                   " open edges before, " + std::to_string(joinedTopology.boundaryEdges) + " after)");
      mesh = std::move(joined);
      topology = std::move(joinedTopology);
    }
  }
  // Only a mesh that may need it is looked at: a single piece, wound
  // alike and facing out, is as the sign needs it.
  if (topology.consistentlyOriented && topology.signedVolume > 0.0 && topology.components <= 1) return topology;
  const Reorientation turned = orientShells(mesh);
  std::string what;
  if (turned.trianglesTurned > 0)
    what = std::to_string(turned.trianglesTurned) + " of its " + std::to_string(mesh.triangleCount()) +
           " triangles were wound against their neighbours";
  if (turned.shellsTurned > 0)
    what += std::string(what.empty() ? "" : ", and ") + std::to_string(turned.shellsTurned) +
            (turned.shellsTurned == 1 ? " closed shell faced" : " closed shells faced") + " inward, inside no other";
  if (turned.openPiecesTurned > 0)
    what += std::string(what.empty() ? "" : ", and ") + std::to_string(turned.openPiecesTurned) +
            (turned.openPiecesTurned == 1 ? " open piece was" : " open pieces were") + " inside out (a mirrored scan)";
  if (!what.empty())
    log::warning(name + ": " + what + "; turned them over to face out (counter-clockwise seen from outside)");
  if (turned.nestedShellsTurned > 0)
    log::warning(name + ": " + std::to_string(turned.nestedShellsTurned) +
                 (turned.nestedShellsTurned == 1 ? " shell" : " shells") +
                 " inside those faced the wrong way for their depth (a mirrored part's cavities); turned them too");
  if (turned.unorientableEdges > 0)
    log::warning(name + ": " + std::to_string(turned.unorientableEdges) +
                 " edges join triangles that no turning can make agree (a one-sided surface); its inside there is "
                 "uncertain");
  return turned.changed() ? analyzeTopology(mesh) : topology;
}

void sayWhereTheInputIsOpen(const MeshTopology& topology, const std::string& name, const std::string& closing)
{
  if (topology.boundaryEdges == 0) return;
  log::info(name + " is open (" + std::to_string(topology.boundaryEdges) + " edge" +
            (topology.boundaryEdges == 1 ? "" : "s") + " in one triangle only: holes, or a sheet's rim); " + closing +
            ", its inside being where the winding number exceeds 1/2");
}

}  // namespace lbmshape
