#include "lbmshape/mesh/single_precision.hpp"

#include <algorithm>
#include <cmath>

namespace lbmshape {

glm::dvec3 singlePrecisionOrigin(const TriangleMesh& mesh)
{
  if (mesh.triangles.empty()) return glm::dvec3(0.0);
  const Bounds box = bounds(mesh);
  const glm::dvec3 farthest = glm::max(glm::abs(box.min), glm::abs(box.max));
  const double magnitude = std::max({farthest.x, farthest.y, farthest.z});
  return magnitude > farForItsSize * box.diagonal() ? box.centre() : glm::dvec3(0.0);
}

double singlePrecisionRounding(const TriangleMesh& mesh, const glm::dvec3& origin)
{
  double worst = 0.0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 p = mesh.positions[t[k]] - origin;
      worst = std::max(worst, glm::length(glm::dvec3(glm::vec3(p)) - p));
    }
  return worst;
}

}  // namespace lbmshape
