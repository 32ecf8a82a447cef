#include "lbmshape/mesh/icosphere.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <string>
#include <vector>

#include "lbmshape/core/error.hpp"

namespace lbmshape {

TriangleMesh icosphere(int subdivisions, double radius, glm::dvec3 centre)
{
  if (subdivisions < 0 || subdivisions > maxIcosphereSubdivisions)
    throw UsageError("icosphere: subdivisions " + std::to_string(subdivisions) + " is outside 0 to " +
                     std::to_string(maxIcosphereSubdivisions));
  if (!(std::isfinite(radius) && radius > 0.0) || !std::isfinite(centre.x + centre.y + centre.z))
    throw UsageError("icosphere: the radius must be a finite number above 0 and the centre finite");
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh m;
  m.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& p : m.positions) p = glm::normalize(p);
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
    auto mid = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      auto [it, inserted] = middle.try_emplace(key, uint32_t(m.positions.size()));
      if (inserted) m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
      return it->second;
    };
    std::vector<glm::uvec3> finer;
    for (const auto& f : m.triangles) {
      const uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({ab, f[1], bc});
      finer.push_back({ca, bc, f[2]});
      finer.push_back({ab, bc, ca});
    }
    m.triangles = std::move(finer);
  }
  for (auto& p : m.positions) p = centre + radius * p;
  return m;
}

}  // namespace lbmshape
