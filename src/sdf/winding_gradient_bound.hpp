// How fast the generalized winding number can change away from the surface.
//
// The solid angle a surface subtends is the magnetic scalar potential of a
// unit current around its boundary, so its gradient is a Biot-Savart line
// integral over that boundary alone:
//   grad w(x) = 1/(4 pi) sum over boundary edges of integral (y - x) x dl / |y - x|^3,
// hence |grad w(x)| <= 1/(4 pi) sum_e length_e / dist(x, e)^2.
// For a triangle soup the boundary is the sum of all triangles' directed
// edges, where a->b and b->a cancel: a closed mesh, even a non-manifold or
// self-intersecting one, has none left and w is constant off the surface;
// a mesh with holes keeps only the holes' rims. Edges are matched by vertex
// position, so a soup with duplicated vertices still cancels; edges that
// overlap without sharing both endpoints are kept, which only makes the
// bound larger (safe).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

class WindingGradientBound {
public:
  explicit WindingGradientBound(const TriangleMesh& mesh);

  // Directed edges left after cancellation (counted with multiplicity).
  size_t openEdgeCount() const { return openEdges_; }

  // An upper bound of |grad w| (per world unit) over the box [lo, hi]:
  // infinity when a boundary edge may touch the box. Stops as soon as the
  // bound exceeds `limit`, returning some value above it.
  double over(const glm::dvec3& lo, const glm::dvec3& hi, double limit) const;

private:
  struct Edge {
    glm::dvec3 a, b;
    double weight;  // length times the number of uncancelled copies
  };
  struct Node {
    glm::dvec3 lo, hi;
    double weight;   // sum over the node's edges
    uint32_t first;  // leaf: first edge; inner: second child (the first follows)
    uint32_t count;  // leaf: edge count; 0 for an inner node
  };
  void build();

  std::vector<Edge> edges_;
  std::vector<Node> nodes_;
  size_t openEdges_ = 0;
};

}  // namespace lbmshape
