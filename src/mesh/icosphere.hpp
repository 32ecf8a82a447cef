// The sphere as a mesh: a subdivided icosahedron, whose triangles are all
// nearly the same size (a UV sphere crowds them at the poles).
#pragma once

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// An icosahedron split `subdivisions` times (20 * 4^n triangles), its
// vertices on the sphere; triangles outward.
TriangleMesh icosphere(int subdivisions, double radius = 1.0, glm::dvec3 centre = glm::dvec3(0.0));

}  // namespace lbmshape
