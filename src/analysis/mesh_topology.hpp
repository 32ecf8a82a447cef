// Counts that say whether a mesh is a closed, oriented 2-manifold, and of
// what genus. The definitions are those of the shared meshes' checker
// (../shared/assets/tools/meshtool.py), so results compare with its README.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

struct MeshTopology {
  size_t vertices = 0;              // all positions
  size_t unreferencedVertices = 0;  // positions no triangle uses
  size_t triangles = 0;
  // Triangles that repeat a vertex index. They are left out of the edges,
  // the fans and the Euler characteristic (but count in components and area).
  size_t degenerateTriangles = 0;
  size_t edges = 0;                  // distinct undirected edges
  size_t components = 0;             // sets of triangles joined through shared vertices
  size_t boundaryEdges = 0;          // in one triangle
  size_t nonManifoldEdges = 0;       // in three or more triangles
  size_t nonManifoldVertices = 0;    // whose triangles form more than one fan joined through edges
  size_t inconsistentEdges = 0;      // in two triangles that run it the same way
  bool consistentlyOriented = true;  // no inconsistent edge
  // At least one triangle and none of the defects above: no boundary, no
  // non-manifold edge or vertex, no inconsistent edge, no degenerate triangle.
  bool closedManifold = false;
  int64_t eulerCharacteristic = 0;  // referenced vertices - edges + non-degenerate triangles
  // Sum of the components' genera, (2 components - Euler characteristic) / 2;
  // only when closedManifold (the formula means nothing otherwise).
  std::optional<int64_t> genus;
  double area = 0.0;
  // By the divergence theorem: the enclosed volume when the mesh is a closed
  // manifold with outward normals, negative when they point inward.
  double signedVolume = 0.0;
};

// Throws InputError when a triangle refers to a vertex the mesh lacks.
MeshTopology analyzeTopology(const TriangleMesh& mesh);

// MeshTopology's area and signedVolume alone (the same sums, in the same
// order), for a mesh whose indices are known to be in range.
struct AreaAndVolume {
  double area = 0.0, signedVolume = 0.0;
};
AreaAndVolume areaAndSignedVolume(const TriangleMesh& mesh);

}  // namespace lbmshape
