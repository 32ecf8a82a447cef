// Small meshes built in code, with known topology and geometry.
#pragma once

#include <functional>

#include <glm/glm.hpp>

#include "lbmshape/mesh/icosphere.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape::testing {

// An axis-aligned box of 12 triangles, outward.
TriangleMesh box(const glm::dvec3& lo, const glm::dvec3& hi);
// Corners (0,0,0), (1,0,0), (0,1,0), (0,0,1); outward triangles.
TriangleMesh tetrahedron();
// An icosahedron split `subdivisions` times (20 * 4^n triangles), vertices on the sphere; outward.
using lbmshape::icosphere;
// A torus around z: `rings` steps around the axis, `sides` around the tube; outward.
TriangleMesh torusMesh(double R, double r, int rings, int sides);
// An open sheet: an n x n grid of quads over (u, v) in [0, 1]^2, two
// triangles each, with `place` putting each grid point in space.
TriangleMesh sheet(int n, const std::function<glm::dvec3(double u, double v)>& place);
// Both meshes in one, b's indices shifted.
TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b);
// Every position p becomes centre + scale * (p - centre).
TriangleMesh scaled(TriangleMesh mesh, double scale, glm::dvec3 centre = glm::dvec3(0.0));
// The triangles whose centroid lies at z >= 0, or z < 0 (the vertices kept
// as they are): of an icosphere, the upper or lower hemisphere, open at
// its rim.
TriangleMesh upperHalf(const TriangleMesh& mesh);
TriangleMesh lowerHalf(const TriangleMesh& mesh);

// The smallest of a triangle's three angles, in degrees.
double smallestAngle(const TriangleMesh& mesh, const glm::uvec3& triangle);
// The triangles with an angle under `degrees`: marching cubes' slivers.
size_t triangleCountWithAngleUnder(const TriangleMesh& mesh, double degrees);

}  // namespace lbmshape::testing
