// A bounding volume hierarchy over a triangle soup, answering the two
// questions a signed distance field asks of every cell: how far is the
// surface (exact closest point), and is this point inside (the generalized
// winding number, which stays meaningful for open, non-manifold and
// self-intersecting meshes).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

class TriangleBvh {
public:
  static constexpr uint32_t kNoTriangle = std::numeric_limits<uint32_t>::max();
  // Barill et al.'s accuracy parameter: a cluster is replaced by its
  // expansion when the query is farther than beta times its radius (here a
  // bound on it, from the cluster's box). 3 keeps the error near 1e-3 at
  // worst (mean 2e-4) on the shared meshes; 2 is 1.4 times faster with
  // errors up to 5e-3.
  static constexpr double kDefaultBeta = 3.0;

  // What the tree is for: closest points alone need no far-field expansions,
  // whose building costs more than the tree's (the mesh comparisons).
  enum class Queries { ClosestAndWinding, ClosestOnly };

  // Copies what it needs; the mesh may be open, non-manifold or
  // self-intersecting. Throws InputError for an index past the vertices or a
  // non-finite position used by a triangle.
  // Built by OpenMP tasks: on the main thread only, as LLVM's OpenMP
  // runtime (libomp 14) aborts in its task allocator ("kmp_alloc.cpp(2173):
  // q_th != NULL") when a second thread of the process (the morph's frame
  // writer) runs tasks beside the main one's parallel regions.
  explicit TriangleBvh(const TriangleMesh& mesh, Queries queries = Queries::ClosestAndWinding);

  struct Closest {
    double distance;    // Euclidean, in the mesh's units
    glm::dvec3 point;   // on the surface
    uint32_t triangle;  // index into the mesh's triangles
  };

  // Exact closest point on the surface. With no triangles: {inf, p, kNoTriangle}.
  Closest closest(const glm::dvec3& p) const;
  // The same, pruning everything farther than upperBound. Exact when the
  // surface is within upperBound of p; otherwise {inf, p, kNoTriangle}, which
  // makes this also the fast test "is any triangle within upperBound?".
  Closest closest(const glm::dvec3& p, double upperBound) const;

  // Generalized winding number (Jacobson et al. 2013): 1 inside a closed
  // outward-oriented surface, 0 outside, in between near holes. Hierarchical
  // approximation (Barill et al. 2018, expansion to second order), within
  // about 1e-3 of the exact value, near the surface as well as far from it.
  // Only for a tree built with Queries::ClosestAndWinding.
  double windingNumber(const glm::dvec3& p) const { return windingNumber(p, kDefaultBeta); }
  double windingNumber(const glm::dvec3& p, double beta) const;
  // Brute-force sum of solid angles over all triangles: slow, the test oracle.
  double exactWindingNumber(const glm::dvec3& p) const;

  size_t triangleCount() const { return triangles_.size(); }
  // Bounding box of one triangle (mesh index).
  void triangleBounds(uint32_t triangle, glm::dvec3& lo, glm::dvec3& hi) const
  {
    const Triangle& t = triangles_[slotOf_[triangle]];
    lo = glm::min(t.a, glm::min(t.b, t.c));
    hi = glm::max(t.a, glm::max(t.b, t.c));
  }
  // Corners of one triangle (mesh index).
  void triangleCorners(uint32_t triangle, glm::dvec3& a, glm::dvec3& b, glm::dvec3& c) const
  {
    const Triangle& t = triangles_[slotOf_[triangle]];
    a = t.a, b = t.b, c = t.c;
  }
  // Closest point of one triangle (mesh index) to p, by the same arithmetic as closest().
  Closest closestOnTriangle(const glm::dvec3& p, uint32_t triangle) const;

  // The tree as it is laid out, for a copy of it on the device
  // (device_band_distances.cpp): nodes depth first from the root, their
  // triangles by slot (the leaves' order).
  struct Node {
    glm::dvec3 lo, hi;  // bounds of the node's triangles
    uint32_t first;     // leaf: first triangle slot; inner: index of the second child (the first is next)
    uint32_t count;     // leaf: number of triangles; 0 for an inner node
  };
  const std::vector<Node>& nodes() const { return nodes_; }
  void slotCorners(uint32_t slot, glm::dvec3& a, glm::dvec3& b, glm::dvec3& c) const
  {
    const Triangle& t = triangles_[slot];
    a = t.a, b = t.b, c = t.c;
  }

  // Deeper than any tree build() makes (see there), so fixed-size traversal
  // stacks of kMaxDepth + 2 entries suffice (the device's too).
  static constexpr int kMaxDepth = 128;

private:
  // Barill et al.'s per-node data: the node's triangles seen from afar, as
  // moments of their area-weighted normals about the area centroid.
  struct Expansion {
    glm::dvec3 centre{0.0};  // area-weighted centroid
    double radius = 0.0;     // bounds every triangle's distance from centre
    glm::dvec3 normal{0.0};  // order 0: sum of area vectors nu (area times unit normal)
    glm::dmat3 first{0.0};   // order 1: first[n][d] = sum of nu_n (centroid - centre)_d
    glm::dmat3 second[3];    // order 2: second[n] = sum of nu_n * mean of (y - centre)(y - centre)^T over the triangle
  };
  struct Triangle {
    glm::dvec3 a, b, c;
  };

  void build();
  void buildExpansions();
  double expansionWinding(const Expansion& e, const glm::dvec3& p) const;

  std::vector<Triangle> triangles_;    // in leaf order
  std::vector<uint32_t> meshIndex_;    // slot -> mesh triangle
  std::vector<uint32_t> slotOf_;       // mesh triangle -> slot
  std::vector<Node> nodes_;            // depth first; nodes_[0] is the root
  std::vector<Expansion> expansions_;  // per node
};

}  // namespace lbmshape
