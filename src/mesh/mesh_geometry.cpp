#include "lbmshape/mesh/mesh_geometry.hpp"

#include <algorithm>

namespace lbmshape {

glm::dvec3 triangleAreaVector(const TriangleMesh& mesh, const glm::uvec3& t)
{
  const glm::dvec3& a = mesh.positions[t[0]];
  return glm::cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a);
}

bool isDegenerate(const TriangleMesh& mesh, const glm::uvec3& t)
{
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
  const glm::dvec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
  const double longest = std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
  return 0.5 * glm::length(glm::cross(b - a, c - a)) <= 1e-12 * longest * longest;
}

std::vector<glm::dvec3> areaWeightedNormals(const TriangleMesh& mesh)
{
  std::vector<glm::dvec3> normals(mesh.positions.size(), glm::dvec3(0.0));
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 area = triangleAreaVector(mesh, t);
    for (int k = 0; k < 3; ++k) normals[t[k]] += area;
  }
  for (auto& n : normals) {
    const double length = glm::length(n);
    n = length > 0 ? n / length : glm::dvec3(0.0);
  }
  return normals;
}

double surfaceArea(const TriangleMesh& mesh)
{
  double twice = 0.0;
  for (const auto& t : mesh.triangles) twice += glm::length(triangleAreaVector(mesh, t));
  return twice / 2.0;
}

double meanEdgeLength(const TriangleMesh& mesh)
{
  if (mesh.triangles.empty()) return 0.0;
  double sum = 0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) sum += glm::distance(mesh.positions[t[k]], mesh.positions[t[(k + 1) % 3]]);
  return sum / double(3 * mesh.triangles.size());
}

}  // namespace lbmshape
