// Exact geometry of one triangle seen from a point: the closest point on it
// and the solid angle it subtends. The signed distance field is built from
// these two primitives, so both accept any triangle, degenerate ones included.
// They run in the innermost loops, hence inline.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace lbmshape {

// The point of segment [a, b] nearest to p; a itself when a == b.
inline glm::dvec3 closestPointOnSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b)
{
  const glm::dvec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  if (!(length2 > 0.0)) return a;
  const double t = std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0);
  return a + t * ab;
}

namespace detail {

inline glm::dvec3 closestPointOnEdges(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                      const glm::dvec3& c)
{
  glm::dvec3 best = closestPointOnSegment(p, a, b);
  double best2 = glm::dot(best - p, best - p);
  for (const glm::dvec3& q : {closestPointOnSegment(p, b, c), closestPointOnSegment(p, c, a)}) {
    const double d2 = glm::dot(q - p, q - p);
    if (d2 < best2) best = q, best2 = d2;
  }
  return best;
}

}  // namespace detail

// A triangle and what its closest-point queries share, computed once (the
// exact band asks each triangle about every cell around it). Triangles with
// (almost) no area, from repeated or collinear vertices, are treated as the
// segments they are: a sliver thinner than 1e-6 of its edges is its edges to
// within that width. Every other triangle has edges of positive length, so
// no division below can be by zero.
// Ericson, Real-Time Collision Detection (2005), 5.1.5: find the Voronoi
// region of p (three vertices, three edges, the face) with a few dot
// products, then project onto that feature. Of the six dot products only d1
// and d2 depend on the point; d3 to d6 follow from them (bp = ap - ab,
// cp = ap - ac).
class PreparedTriangle {
public:
  PreparedTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
      : a_(a), b_(b), c_(c), ab_(b - a), ac_(c - a), bc_(c - b)
  {
    const glm::dvec3 normal = glm::cross(ab_, ac_);
    abab_ = glm::dot(ab_, ab_), acac_ = glm::dot(ac_, ac_), abac_ = glm::dot(ab_, ac_);
    sliver_ = !(glm::dot(normal, normal) > 1e-12 * abab_ * acac_);
  }

  glm::dvec3 closestPoint(const glm::dvec3& p) const
  {
    if (sliver_) return detail::closestPointOnEdges(p, a_, b_, c_);
    const glm::dvec3 ap = p - a_;
    const double d1 = glm::dot(ab_, ap), d2 = glm::dot(ac_, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a_;
    const double d3 = d1 - abab_, d4 = d2 - abac_;
    if (d3 >= 0.0 && d4 <= d3) return b_;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a_ + (d1 / (d1 - d3)) * ab_;
    const double d5 = d1 - abac_, d6 = d2 - acac_;
    if (d6 >= 0.0 && d5 <= d6) return c_;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a_ + (d2 / (d2 - d6)) * ac_;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b_ + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * bc_;
    // Face region: va + vb + vc is |ab x ac|^2, but computed from differences
    // of products; clamping keeps rounding from leaving the triangle.
    const double denominator = 1.0 / (va + vb + vc);
    const double v = std::clamp(vb * denominator, 0.0, 1.0), w = std::clamp(vc * denominator, 0.0, 1.0 - v);
    return a_ + v * ab_ + w * ac_;
  }

  // Whether the triangle counts as its three edges (the device's distances,
  // device_band_distances.cpp, ask the same).
  bool isSliver() const { return sliver_; }

  // The squared distance from p to the triangle.
  double distance2(const glm::dvec3& p) const
  {
    const glm::dvec3 gap = closestPoint(p) - p;
    return glm::dot(gap, gap);
  }

private:
  glm::dvec3 a_, b_, c_, ab_, ac_, bc_;
  double abab_, acac_, abac_;
  bool sliver_;
};

// The point of triangle (a, b, c) nearest to p (PreparedTriangle, for one query).
inline glm::dvec3 closestPointOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                         const glm::dvec3& c)
{
  return PreparedTriangle(a, b, c).closestPoint(p);
}

// Signed solid angle of triangle (a, b, c) seen from p (van Oosterom and
// Strackee 1983), in (-2 pi, 2 pi); positive when the triangle's
// counter-clockwise normal points away from p, so that the solid angles of a
// closed, outward-oriented mesh add up to 4 pi inside and 0 outside.
inline double solidAngle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  const glm::dvec3 u = a - p, v = b - p, w = c - p;
  const double lu = glm::length(u), lv = glm::length(v), lw = glm::length(w);
  const double numerator = glm::dot(u, glm::cross(v, w));
  const double denominator = lu * lv * lw + glm::dot(u, v) * lw + glm::dot(v, w) * lu + glm::dot(w, u) * lv;
  return 2.0 * std::atan2(numerator, denominator);
}

}  // namespace lbmshape
