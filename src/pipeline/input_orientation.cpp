#include "lbmshape/pipeline/input_orientation.hpp"

#include <utility>
#include <vector>

#include "lbmshape/core/log.hpp"
#include "lbmshape/analysis/joined_seams.hpp"
#include "lbmshape/sdf/shell_orientation.hpp"

namespace lbmshape {

MeshTopology orientTheInput(TriangleMesh& mesh, const std::string& name)
{
  JoinedSeams seams = joinSeams(mesh);
  MeshTopology topology = std::move(seams.topology);
  if (seams.joined) {
    log::verbose(name + ": " + std::to_string(seams.joinedVertices) +
                 " vertices at the positions of others joined to them (" + std::to_string(seams.boundaryEdgesBefore) +
                 " open edges before, " + std::to_string(topology.boundaryEdges) + " after)");
    mesh = std::move(*seams.joined);
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
