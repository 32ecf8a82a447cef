#include "lbmshape/analysis/joined_seams.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

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
  // Of the vertices the triangles use: welding starts from the corners, so
  // a vertex no triangle uses is not "joined".
  std::vector<uint8_t> used(mesh.positions.size(), 0);
  for (const glm::uvec3& t : mesh.triangles) used[t.x] = used[t.y] = used[t.z] = 1;
  const size_t usedCount = size_t(std::count(used.begin(), used.end(), uint8_t(1)));
  seams.joinedVertices = usedCount - joined.vertexCount();
  seams.topology = std::move(joinedTopology);
  seams.joined = std::move(joined);
  return seams;
}

}  // namespace lbmshape
