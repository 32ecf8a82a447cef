#include "lbmshape/analysis/joined_seams.hpp"

#include <utility>

#include "lbmshape/mesh/vertex_welding.hpp"

namespace lbmshape {

JoinedSeams joinSeams(const TriangleMesh& mesh)
{
  JoinedSeams seams{analyzeTopology(mesh), std::nullopt, 0, 0};
  seams.boundaryEdgesBefore = seams.topology.boundaryEdges;
  if (seams.topology.boundaryEdges == 0) return seams;
  TriangleMesh joined = weldEqualPositions(mesh);
  MeshTopology joinedTopology = analyzeTopology(joined);
  if (joinedTopology.boundaryEdges >= seams.topology.boundaryEdges) return seams;
  seams.joinedVertices = mesh.vertexCount() - joined.vertexCount();
  seams.topology = std::move(joinedTopology);
  seams.joined = std::move(joined);
  return seams;
}

}  // namespace lbmshape
