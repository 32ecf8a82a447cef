#include "sdf_fixtures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace lbmshape::testing::sdf {

TriangleMesh withHoles(const TriangleMesh& mesh, size_t count, uint32_t seed)
{
  // Every k-th triangle after a random start: the mesh's triangle order
  // follows its surface closely enough that this spreads the holes out.
  std::mt19937 rng(seed);
  const size_t n = mesh.triangles.size(), stride = n / count;
  std::vector<bool> drop(n, false);
  const size_t start = std::uniform_int_distribution<size_t>(0, stride - 1)(rng);
  for (size_t k = 0; k < count; ++k) drop[(start + k * stride) % n] = true;
  TriangleMesh out;
  out.positions = mesh.positions;
  for (size_t t = 0; t < n; ++t)
    if (!drop[t]) out.triangles.push_back(mesh.triangles[t]);
  return out;
}

double innerRadius(const TriangleMesh& sphere, const glm::dvec3& centre)
{
  double r = std::numeric_limits<double>::infinity();
  for (const auto& t : sphere.triangles) {
    const glm::dvec3 a = sphere.positions[t.x], b = sphere.positions[t.y], c = sphere.positions[t.z];
    const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
    r = std::min(r, std::abs(glm::dot(n, a - centre)));
  }
  return r;
}

namespace {

double segmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b)
{
  const glm::dvec3 ab = b - a;
  const double l2 = glm::dot(ab, ab);
  const double s = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + s * ab));
}

double triangleDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  double best = std::min({segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a)});
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double n2 = glm::dot(n, n);
  if (n2 > 0.0) {
    // Barycentric coordinates of the projection from sub-triangle areas.
    const glm::dvec3 q = p - glm::dot(p - a, n) / n2 * n;
    const double u = glm::dot(glm::cross(c - b, q - b), n) / n2;
    const double v = glm::dot(glm::cross(a - c, q - c), n) / n2;
    const double w = 1.0 - u - v;
    if (u >= 0.0 && v >= 0.0 && w >= 0.0) best = std::min(best, glm::length(p - q));
  }
  return best;
}

}  // namespace

double bruteForceDistance(const TriangleMesh& mesh, const glm::dvec3& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles)
    best = std::min(best, triangleDistance(p, mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]));
  return best;
}

double bruteForceWindingNumber(const TriangleMesh& mesh, const glm::dvec3& p)
{
  double sum = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 u = glm::normalize(mesh.positions[t.x] - p), v = glm::normalize(mesh.positions[t.y] - p),
                     w = glm::normalize(mesh.positions[t.z] - p);
    // Sides of the spherical triangle, then L'Huilier's spherical excess.
    auto angle = [](const glm::dvec3& x, const glm::dvec3& y) {
      return std::acos(std::clamp(glm::dot(x, y), -1.0, 1.0));
    };
    const double a = angle(v, w), b = angle(w, u), c = angle(u, v);
    const double s = 0.5 * (a + b + c);
    const double product = std::tan(s / 2) * std::tan((s - a) / 2) * std::tan((s - b) / 2) * std::tan((s - c) / 2);
    const double excess = 4.0 * std::atan(std::sqrt(std::max(product, 0.0)));
    const double orientation = glm::dot(u, glm::cross(v, w));
    sum += orientation > 0.0 ? excess : orientation < 0.0 ? -excess : 0.0;
  }
  return sum / (4.0 * std::numbers::pi);
}

glm::dvec3 randomPoint(std::mt19937& rng, double scale)
{
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

}  // namespace lbmshape::testing::sdf
