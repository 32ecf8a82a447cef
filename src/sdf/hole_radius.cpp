#include "lbmshape/sdf/hole_radius.hpp"

#include <algorithm>
#include <cmath>
#include <parallel/algorithm>
#include <utility>
#include <vector>

#include "lbmshape/core/concurrent_union_find.hpp"

namespace lbmshape {

double widestHoleRadius(const TriangleMesh& mesh)
{
  // Each directed edge a->b counts +1 on key (min, max) when a < b and -1
  // otherwise: what is left after summing is the rims.
  std::vector<std::pair<uint64_t, int>> keyed;
  keyed.reserve(3 * mesh.triangles.size());
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = t[k], b = t[(k + 1) % 3];
      if (a != b) keyed.emplace_back(uint64_t(std::min(a, b)) << 32 | std::max(a, b), a < b ? 1 : -1);
    }
  __gnu_parallel::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  ConcurrentUnionFind rims(mesh.positions.size());
  std::vector<uint8_t> onRim(mesh.positions.size(), 0);
  bool open = false;
  for (size_t i = 0; i < keyed.size();) {
    size_t j = i;
    int net = 0;
    for (; j < keyed.size() && keyed[j].first == keyed[i].first; ++j) net += keyed[j].second;
    if (net != 0) {
      const uint32_t a = uint32_t(keyed[i].first >> 32), b = uint32_t(keyed[i].first & 0xffffffffu);
      rims.unite(a, b);
      onRim[a] = onRim[b] = 1;
      open = true;
    }
    i = j;
  }
  if (!open) return 0.0;
  const std::vector<uint32_t> rimOf = std::move(rims).roots();
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
  std::vector<uint32_t> count(mesh.positions.size(), 0);
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (onRim[v]) {
      sum[rimOf[v]] += mesh.positions[v];
      ++count[rimOf[v]];
    }
  double widest = 0.0;
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (onRim[v]) {
      const glm::dvec3 centroid = sum[rimOf[v]] / double(count[rimOf[v]]);
      widest = std::max(widest, glm::length(mesh.positions[v] - centroid));
    }
  return widest;
}

double halfWidthOverHoles(const TriangleMesh& mesh, double voxel, double halfWidth)
{
  const double radius = widestHoleRadius(mesh) / voxel;
  if (radius == 0.0) return halfWidth;
  return std::max(halfWidth, std::ceil(1.25 * radius) + 1.0);
}

}  // namespace lbmshape
