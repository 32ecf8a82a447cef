// A mesh's seams joined, as lbmshape reads a mesh for its work: a file that
// numbers the vertices along a seam twice (a glTF split at its UV seams or
// into a primitive per material, a triangle soup) is one surface again.
// denoise and morph work on it so (pipeline/input_orientation.hpp), and
// compare reports its topology so, where the two used to disagree ("2
// components, 414 boundary edges" of a file denoise took as one closed
// surface).
#pragma once

#include <cstddef>
#include <optional>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

struct JoinedSeams {
  MeshTopology topology;               // of the joined mesh where there is one, else of the mesh
  std::optional<TriangleMesh> joined;  // where joining equal positions closed edges
  size_t joinedVertices = 0;           // vertices that joined others
  size_t boundaryEdgesBefore = 0;      // of the mesh as it was
};

// Joins the vertices at equal positions (weldEqualPositions) only where
// that leaves fewer open edges: an open mesh's own rims stay as they are.
JoinedSeams joinSeams(const TriangleMesh& mesh);

}  // namespace lbmshape
