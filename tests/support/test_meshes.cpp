#include "support/test_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace lbmshape::testing {

TriangleMesh box(const glm::dvec3& lo, const glm::dvec3& hi)
{
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k) mesh.positions.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  // Two triangles per face, counter-clockwise seen from outside.
  mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},   // z = lo, z = hi
                    {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},   // y = lo, y = hi
                    {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};  // x = lo, x = hi
  return mesh;
}

TriangleMesh tetrahedron()
{
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

TriangleMesh torusMesh(double R, double r, int rings, int sides)
{
  TriangleMesh m;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const double u = 2 * std::numbers::pi * i / rings, v = 2 * std::numbers::pi * j / sides;
      const double ring = R + r * std::cos(v);
      m.positions.push_back({ring * std::cos(u), ring * std::sin(u), r * std::sin(v)});
    }
  auto at = [&](int i, int j) { return uint32_t((i % rings) * sides + (j % sides)); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

TriangleMesh sheet(int n, const std::function<glm::dvec3(double u, double v)>& place)
{
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back(place(double(i) / n, double(j) / n));
  // Corners a b / c d: triangles (a, b, d) and (a, d, c).
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n) + 1, d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  return m;
}

TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b)
{
  TriangleMesh m = a;
  const uint32_t shift = uint32_t(a.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (const auto& t : b.triangles) m.triangles.push_back(t + shift);
  m.normals.clear();
  return m;
}

TriangleMesh scaled(TriangleMesh mesh, double scale, glm::dvec3 centre)
{
  for (auto& p : mesh.positions) p = centre + scale * (p - centre);
  return mesh;
}

namespace {
TriangleMesh half(const TriangleMesh& mesh, bool upper)
{
  TriangleMesh kept;
  kept.positions = mesh.positions;
  for (const glm::uvec3& t : mesh.triangles)
    if ((mesh.positions[t.x].z + mesh.positions[t.y].z + mesh.positions[t.z].z >= 0.0) == upper)
      kept.triangles.push_back(t);
  return kept;
}
}  // namespace

TriangleMesh upperHalf(const TriangleMesh& mesh) { return half(mesh, true); }
TriangleMesh lowerHalf(const TriangleMesh& mesh) { return half(mesh, false); }

double smallestAngle(const TriangleMesh& mesh, const glm::uvec3& triangle)
{
  const glm::dvec3 p[3] = {mesh.positions[triangle.x], mesh.positions[triangle.y], mesh.positions[triangle.z]};
  double smallest = 180.0;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 u = glm::normalize(p[(k + 1) % 3] - p[k]), v = glm::normalize(p[(k + 2) % 3] - p[k]);
    smallest = std::min(smallest, std::acos(std::clamp(glm::dot(u, v), -1.0, 1.0)) * 180.0 / std::numbers::pi);
  }
  return smallest;
}

size_t triangleCountWithAngleUnder(const TriangleMesh& mesh, double degrees)
{
  return size_t(std::count_if(mesh.triangles.begin(), mesh.triangles.end(),
                              [&](const glm::uvec3& t) { return smallestAngle(mesh, t) < degrees; }));
}

}  // namespace lbmshape::testing
