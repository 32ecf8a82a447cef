// The winding-number half of TriangleBvh: per-node far-field expansions and
// the hierarchical sum of Barill et al., "Fast Winding Numbers for Soups and
// Clouds" (SIGGRAPH 2018).
//
// A triangle t with area vector nu_t (area times unit normal) seen from q
// subtends, to first order, nu_t . G(y - q) with G(r) = r / |r|^3; a node's
// triangles seen from farther than beta times its radius are summed as one
// Taylor expansion of G about the node's area centroid. The order-k term
// needs the moments sum_t nu_t (x) integral_t (y - centre)^(x)k dA, which
// are exact for triangles (centroid for k = 1, the triangle's second-moment
// formula for k = 2) and are carried up the tree with the parallel-axis
// shifts below, so building costs O(nodes).
#include <cmath>
#include <numbers>

#include "lbmshape/sdf/point_triangle.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

#include <stdexcept>

namespace lbmshape {

void TriangleBvh::buildExpansions()
{
  expansions_.assign(nodes_.size(), Expansion{});
  std::vector<double> area(nodes_.size(), 0.0);
  // Leaves from their triangles (most of the work, independent)...
#pragma omp parallel for schedule(dynamic, 256)
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const Node& node = nodes_[i];
    if (node.count == 0) continue;
    Expansion& e = expansions_[i];
    glm::dvec3 weighted(0.0);
    for (uint32_t s = node.first; s < node.first + node.count; ++s) {
      const Triangle& t = triangles_[s];
      const double a = 0.5 * glm::length(glm::cross(t.b - t.a, t.c - t.a));
      area[i] += a;
      weighted += a * (t.a + t.b + t.c) / 3.0;
    }
    e.centre = area[i] > 0.0 ? weighted / area[i] : 0.5 * (node.lo + node.hi);
    for (uint32_t s = node.first; s < node.first + node.count; ++s) {
      const Triangle& t = triangles_[s];
      const glm::dvec3 nu = 0.5 * glm::cross(t.b - t.a, t.c - t.a);
      const glm::dvec3 v[3] = {t.a - e.centre, t.b - e.centre, t.c - e.centre};
      const glm::dvec3 sum = v[0] + v[1] + v[2];
      // Mean of (y - centre)(y - centre)^T over the triangle.
      const glm::dmat3 moment = (glm::outerProduct(v[0], v[0]) + glm::outerProduct(v[1], v[1]) +
                                 glm::outerProduct(v[2], v[2]) + glm::outerProduct(sum, sum)) /
                                12.0;
      for (int k = 0; k < 3; ++k) e.radius = std::max(e.radius, glm::length(v[k]));
      e.normal += nu;
      for (int n = 0; n < 3; ++n) {
        e.first[n] += nu[n] * sum / 3.0;
        e.second[n] += nu[n] * moment;
      }
    }
  }
  // ...then inner nodes from their children. Children follow their parent
  // in the depth-first layout, so walking backwards meets them first.
  for (size_t i = nodes_.size(); i-- > 0;) {
    const Node& node = nodes_[i];
    if (node.count > 0) continue;
    Expansion& e = expansions_[i];
    const size_t children[2] = {i + 1, node.first};
    area[i] = area[children[0]] + area[children[1]];
    e.centre = area[i] > 0.0 ? (area[children[0]] * expansions_[children[0]].centre +
                                area[children[1]] * expansions_[children[1]].centre) /
                                   area[i]
                             : 0.5 * (node.lo + node.hi);
    // The radius from the children's grows with every level; the farthest
    // corner of the node's box does not.
    double corner = 0.0;
    for (int k = 0; k < 8; ++k)
      corner = std::max(corner, glm::length(glm::dvec3(k & 1 ? node.hi.x : node.lo.x, k & 2 ? node.hi.y : node.lo.y,
                                                       k & 4 ? node.hi.z : node.lo.z) -
                                            e.centre));
    for (size_t c : children) {
      const Expansion& child = expansions_[c];
      const glm::dvec3 shift = child.centre - e.centre;  // (y - centre) = (y - child centre) + shift
      e.radius = std::max(e.radius, glm::length(shift) + child.radius);
      e.normal += child.normal;
      for (int n = 0; n < 3; ++n) {
        e.first[n] += child.first[n] + child.normal[n] * shift;
        e.second[n] += child.second[n] + glm::outerProduct(shift, child.first[n]) +
                       glm::outerProduct(child.first[n], shift) + child.normal[n] * glm::outerProduct(shift, shift);
      }
    }
    e.radius = std::min(e.radius, corner);
  }
}

// Solid angle of a node's triangles from p by the expansion of G about
// r = centre - p: G(r) + DG(r) delta + D2G(r) delta delta / 2, with
//   DG_ij    = delta_ij / |r|^3 - 3 r_i r_j / |r|^5
//   D2G_i,jk = -3 (delta_ij r_k + delta_ik r_j + delta_jk r_i) / |r|^5 + 15 r_i r_j r_k / |r|^7
// contracted with the node's moments.
double TriangleBvh::expansionWinding(const Expansion& e, const glm::dvec3& p) const
{
  const glm::dvec3 r = e.centre - p;
  const double r2 = glm::dot(r, r);
  const double inv1 = 1.0 / std::sqrt(r2);
  const double inv3 = inv1 / r2, inv5 = inv3 / r2, inv7 = inv5 / r2;

  const double order0 = glm::dot(e.normal, r) * inv3;

  const double trace1 = e.first[0][0] + e.first[1][1] + e.first[2][2];
  const double order1 = trace1 * inv3 - 3.0 * glm::dot(r, e.first * r) * inv5;

  double twice = 0.0, traces = 0.0, cubic = 0.0;
  for (int n = 0; n < 3; ++n) {
    const glm::dvec3 sr = e.second[n] * r;
    twice += sr[n];
    traces += r[n] * (e.second[n][0][0] + e.second[n][1][1] + e.second[n][2][2]);
    cubic += r[n] * glm::dot(r, sr);
  }
  const double order2 = 0.5 * (-3.0 * (2.0 * twice + traces) * inv5 + 15.0 * cubic * inv7);
  return order0 + order1 + order2;
}

double TriangleBvh::windingNumber(const glm::dvec3& p, double beta) const
{
  if (nodes_.empty()) return 0.0;
  if (expansions_.size() != nodes_.size())
    throw std::logic_error("TriangleBvh::windingNumber on a tree built for closest points only");
  double sum = 0.0;
  uint32_t stack[kMaxDepth + 2];
  int top = 0;
  stack[top++] = 0;
  const double beta2 = beta * beta;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const Expansion& e = expansions_[index];
    const glm::dvec3 d = e.centre - p;
    if (glm::dot(d, d) > beta2 * e.radius * e.radius) {
      sum += expansionWinding(e, p);
      continue;
    }
    const Node& node = nodes_[index];
    if (node.count > 0) {
      for (uint32_t s = node.first; s < node.first + node.count; ++s)
        sum += solidAngle(p, triangles_[s].a, triangles_[s].b, triangles_[s].c);
      continue;
    }
    stack[top++] = node.first;
    stack[top++] = index + 1;
  }
  return sum / (4.0 * std::numbers::pi);
}

double TriangleBvh::exactWindingNumber(const glm::dvec3& p) const
{
  double sum = 0.0;
  for (const Triangle& t : triangles_) sum += solidAngle(p, t.a, t.b, t.c);
  return sum / (4.0 * std::numbers::pi);
}

}  // namespace lbmshape
