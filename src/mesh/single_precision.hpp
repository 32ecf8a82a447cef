// Coordinates stored as 32-bit floats (glTF, PLY, STL) are 2^-24 of their
// magnitude apart: a mesh far from the origin for its size (a georeferenced
// scan at +1e6, a 1 mm part placed 1 m away) loses its detail to that
// spacing, and its triangles collapse. glTF can carry an offset in double
// (a node's translation), so its positions are stored about the mesh's
// centre there; PLY, STL and OFF (as OpenMesh writes it) cannot, and such a
// mesh is refused (writable_mesh.hpp).
#pragma once

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// The point a glTF's float positions are taken about: the origin, or the
// centre of the mesh's bounds where the mesh lies more than
// `farForItsSize` times its own diagonal from the origin, so that an
// ordinary file keeps its positions as they are.
glm::dvec3 singlePrecisionOrigin(const TriangleMesh& mesh);
inline constexpr double farForItsSize = 16.0;

// The most any vertex a triangle uses moves when its coordinates are stored
// as floats about `origin`.
double singlePrecisionRounding(const TriangleMesh& mesh, const glm::dvec3& origin);

}  // namespace lbmshape
