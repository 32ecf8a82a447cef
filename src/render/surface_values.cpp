#include "lbmshape/render/surface_values.hpp"

#include <algorithm>
#include <cmath>

#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

namespace lbmshape::render {
namespace {

// Cotangent of the angle between u and v.
double cotangent(const glm::dvec3& u, const glm::dvec3& v)
{
  const double sine = glm::length(glm::cross(u, v));
  return sine > 0.0 ? glm::dot(u, v) / sine : 0.0;
}

}  // namespace

std::vector<double> vertexMeanCurvature(const TriangleMesh& mesh)
{
  const size_t n = mesh.vertexCount();
  std::vector<glm::dvec3> laplacian(n, glm::dvec3(0.0));
  std::vector<double> area(n, 0.0);
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::dvec3 p[3] = {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
    const uint32_t v[3] = {t.x, t.y, t.z};
    const double triangleArea = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
    double cot[3];
    for (int c = 0; c < 3; ++c) cot[c] = cotangent(p[(c + 1) % 3] - p[c], p[(c + 2) % 3] - p[c]);
    const bool obtuse = cot[0] < 0.0 || cot[1] < 0.0 || cot[2] < 0.0;
    for (int c = 0; c < 3; ++c) {
      // The edge opposite corner c, weighted by half the cotangent there.
      const int i = (c + 1) % 3, j = (c + 2) % 3;
      laplacian[v[i]] += 0.5 * cot[c] * (p[j] - p[i]);
      laplacian[v[j]] += 0.5 * cot[c] * (p[i] - p[j]);
      // Meyer et al.'s mixed area: the Voronoi region of the corner where
      // the triangle is not obtuse, else a half or a quarter of it.
      if (!obtuse) {
        const double toI = glm::dot(p[i] - p[c], p[i] - p[c]), toJ = glm::dot(p[j] - p[c], p[j] - p[c]);
        area[v[c]] += (toI * cot[j] + toJ * cot[i]) / 8.0;
      } else {
        area[v[c]] += cot[c] < 0.0 ? triangleArea / 2.0 : triangleArea / 4.0;
      }
    }
  }
  const std::vector<glm::dvec3> normals = areaWeightedNormals(mesh);
  std::vector<double> curvature(n, 0.0);
  for (size_t i = 0; i < n; ++i)
    // The Laplace-Beltrami operator of the position is -2 H n.
    if (area[i] > 0.0) curvature[i] = -0.5 * glm::dot(laplacian[i] / area[i], normals[i]);
  return curvature;
}

std::vector<double> vertexDistances(const TriangleMesh& mesh, const TriangleBvh& reference)
{
  std::vector<double> distance(mesh.vertexCount());
#pragma omp parallel for schedule(dynamic, 1024)
  for (long i = 0; i < long(distance.size()); ++i)
    distance[size_t(i)] = reference.closest(mesh.positions[size_t(i)]).distance;
  return distance;
}

double quantile(std::vector<double> values, double fraction, bool magnitude)
{
  std::erase_if(values, [](double v) { return !std::isfinite(v); });
  if (values.empty()) return 0.0;
  if (magnitude)
    for (double& v : values) v = std::abs(v);
  const size_t k = std::min(values.size() - 1, size_t(fraction * double(values.size())));
  std::nth_element(values.begin(), values.begin() + long(k), values.end());
  return values[k];
}

}  // namespace lbmshape::render
