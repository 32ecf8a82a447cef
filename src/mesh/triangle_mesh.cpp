#include "lbmshape/mesh/triangle_mesh.hpp"

#include <limits>
#include <string>

#include "lbmshape/core/error.hpp"

namespace lbmshape {

Bounds bounds(const TriangleMesh& mesh)
{
  Bounds b{glm::dvec3(std::numeric_limits<double>::infinity()), glm::dvec3(-std::numeric_limits<double>::infinity())};
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      if (t[k] >= mesh.positions.size())
        throw InputError("a triangle refers to vertex " + std::to_string(t[k]) + " (from 0) of a mesh of " +
                         std::to_string(mesh.positions.size()) + " vertices");
      b.min = glm::min(b.min, mesh.positions[t[k]]);
      b.max = glm::max(b.max, mesh.positions[t[k]]);
    }
  if (mesh.triangles.empty()) b = Bounds{};
  return b;
}

}  // namespace lbmshape
