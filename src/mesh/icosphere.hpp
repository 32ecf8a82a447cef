// The sphere as a mesh: a subdivided icosahedron, whose triangles are all
// nearly the same size (a UV sphere crowds them at the poles).
#pragma once

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// An icosahedron split `subdivisions` times (20 * 4^n triangles), its
// vertices on the sphere; triangles outward. Throws UsageError for
// subdivisions outside 0 to maxIcosphereSubdivisions (9: 5,242,880
// triangles; each more is four times the memory, and 20 filled the
// machine's) or a radius or centre that is not finite (a radius of 0 or
// less too).
inline constexpr int maxIcosphereSubdivisions = 9;
TriangleMesh icosphere(int subdivisions, double radius = 1.0, glm::dvec3 centre = glm::dvec3(0.0));

}  // namespace lbmshape
