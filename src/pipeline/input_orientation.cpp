#include "pipeline/input_orientation.hpp"

#include "core/log.hpp"
#include "sdf/shell_orientation.hpp"

namespace lbmshape {

MeshTopology orientTheInput(TriangleMesh& mesh, const std::string& name)
{
  MeshTopology topology = analyzeTopology(mesh);
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
  if (!what.empty())
    log::warning(name + ": " + what + "; turned them over to face out (counter-clockwise seen from outside)");
  if (turned.unorientableEdges > 0)
    log::warning(name + ": " + std::to_string(turned.unorientableEdges) +
                 " edges join triangles that no turning can make agree (a one-sided surface); its inside there is "
                 "uncertain");
  return turned.changed() ? analyzeTopology(mesh) : topology;
}

}  // namespace lbmshape
