#include "lbmshape/analysis/surface_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "lbmshape/core/error.hpp"

namespace lbmshape {
namespace {

// A double in [0, 1) from the top 53 bits: std::uniform_real_distribution
// differs between standard libraries, this does not.
double unit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

}  // namespace

std::vector<SurfaceSample> sampleSurface(const TriangleMesh& mesh, size_t count, uint64_t seed)
{
  // Cumulative area, so that a uniform number picks a triangle by its area.
  std::vector<double> cumulative(mesh.triangles.size());
  double total = 0.0;
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const glm::uvec3& t = mesh.triangles[i];
    const glm::dvec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    total += std::isfinite(area) ? area : 0.0;
    cumulative[i] = total;
  }
  if (!(total > 0.0) || !std::isfinite(total)) throw InputError("the mesh has no area to sample");

  std::mt19937_64 rng(seed);
  std::vector<SurfaceSample> samples(count);
  for (auto& s : samples) {
    const double pick = unit(rng) * total;
    const size_t i = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
    s.triangle = uint32_t(std::min(i, cumulative.size() - 1));
    // Uniform in the triangle: sqrt warps the first number so that the
    // density does not crowd the first corner.
    const double r = std::sqrt(unit(rng)), u = unit(rng);
    const glm::uvec3& t = mesh.triangles[s.triangle];
    s.point = (1.0 - r) * mesh.positions[t[0]] + r * (1.0 - u) * mesh.positions[t[1]] + r * u * mesh.positions[t[2]];
  }
  std::stable_sort(samples.begin(), samples.end(),
                   [](const SurfaceSample& x, const SurfaceSample& y) { return x.triangle < y.triangle; });
  return samples;
}

std::vector<glm::dvec3> faceNormals(const TriangleMesh& mesh)
{
  std::vector<glm::dvec3> normals(mesh.triangles.size());
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const glm::uvec3& t = mesh.triangles[i];
    const glm::dvec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    normals[i] = length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0.0);
  }
  return normals;
}

}  // namespace lbmshape
