// Small geometric measures of a triangle soup, shared by the readers, the
// writers and the noise generator.
#pragma once

#include <cmath>
#include <vector>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// No coordinate NaN or infinite.
inline bool isFinite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// cross(b - a, c - a): along the normal of triangle (a, b, c) by the
// right-hand rule, with length twice the triangle's area.
glm::dvec3 triangleAreaVector(const TriangleMesh& mesh, const glm::uvec3& triangle);

// Zero area: a repeated corner, or corners collinear to within double
// rounding (area <= 1e-12 x the longest edge squared).
bool isDegenerate(const TriangleMesh& mesh, const glm::uvec3& triangle);

// Per vertex, the normalised sum of the area vectors of the triangles around
// it (so large triangles count more). Zero for a vertex that no triangle with
// area uses, or whose triangles' normals cancel out.
std::vector<glm::dvec3> areaWeightedNormals(const TriangleMesh& mesh);

// The sum of the triangles' areas.
double surfaceArea(const TriangleMesh& mesh);

// The mean length of the three edges of every triangle (an edge two
// triangles share counts twice, a boundary edge once). 0 without triangles.
double meanEdgeLength(const TriangleMesh& mesh);

}  // namespace lbmshape
