#include "lbmshape/sdf/hole_radius.hpp"

#include <algorithm>
#include <cmath>
#include <parallel/algorithm>
#include <utility>
#include <vector>

#include "lbmshape/core/concurrent_union_find.hpp"

namespace lbmshape {
namespace {

// The rims of a mesh's holes: the directed edges left over once every edge
// is cancelled by the edges running it back, each rim the set of them
// joined through shared vertices.
struct HoleRims {
  std::vector<glm::uvec2> edges;  // a -> b, as the mesh's triangles run them (net)
  std::vector<uint32_t> rimOf;    // per vertex: its rim's number, for vertices on a rim
  std::vector<uint8_t> onRim;     // per vertex
  uint32_t count = 0;             // rims
};

HoleRims holeRims(const TriangleMesh& mesh)
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
  HoleRims rims;
  ConcurrentUnionFind joined(mesh.positions.size());
  rims.onRim.assign(mesh.positions.size(), 0);
  for (size_t i = 0; i < keyed.size();) {
    size_t j = i;
    int net = 0;
    for (; j < keyed.size() && keyed[j].first == keyed[i].first; ++j) net += keyed[j].second;
    if (net != 0) {
      const uint32_t low = uint32_t(keyed[i].first >> 32), high = uint32_t(keyed[i].first & 0xffffffffu);
      joined.unite(low, high);
      rims.onRim[low] = rims.onRim[high] = 1;
      // An edge run |net| more times one way: its film is bounded by it as often.
      for (int k = 0; k < std::abs(net); ++k)
        rims.edges.push_back(net > 0 ? glm::uvec2(low, high) : glm::uvec2(high, low));
    }
    i = j;
  }
  if (rims.edges.empty()) return rims;
  const std::vector<uint32_t> roots = std::move(joined).roots();
  std::vector<uint32_t> number(mesh.positions.size(), UINT32_MAX);
  rims.rimOf.assign(mesh.positions.size(), UINT32_MAX);
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (rims.onRim[v]) {
      uint32_t& n = number[roots[v]];
      if (n == UINT32_MAX) n = rims.count++;
      rims.rimOf[v] = n;
    }
  return rims;
}

std::vector<glm::dvec3> rimCentroids(const TriangleMesh& mesh, const HoleRims& rims)
{
  std::vector<glm::dvec3> sum(rims.count, glm::dvec3(0.0));
  std::vector<uint32_t> count(rims.count, 0);
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (rims.onRim[v]) {
      sum[rims.rimOf[v]] += mesh.positions[v];
      ++count[rims.rimOf[v]];
    }
  for (uint32_t r = 0; r < rims.count; ++r) sum[r] /= double(count[r]);
  return sum;
}

}  // namespace

double widestHoleRadius(const TriangleMesh& mesh)
{
  const HoleRims rims = holeRims(mesh);
  if (rims.count == 0) return 0.0;
  const std::vector<glm::dvec3> centroid = rimCentroids(mesh, rims);
  double widest = 0.0;
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (rims.onRim[v]) widest = std::max(widest, glm::length(mesh.positions[v] - centroid[rims.rimOf[v]]));
  return widest;
}

double halfWidthOverHoles(const TriangleMesh& mesh, double voxel, double halfWidth)
{
  const double radius = widestHoleRadius(mesh) / voxel;
  if (radius == 0.0) return halfWidth;
  return std::max(halfWidth, std::ceil(1.25 * radius) + 1.0);
}

ClosingFans closingFans(const TriangleMesh& mesh, double leastArea, const WindingAt& windingAt)
{
  const HoleRims rims = holeRims(mesh);
  ClosingFans fans;
  if (rims.count == 0) return fans;
  const std::vector<glm::dvec3> centroid = rimCentroids(mesh, rims);
  // Each rim's plane: the normal of its fan (the Newell normal of its edges,
  // as the triangles run them, which does not need them ordered in a loop).
  std::vector<glm::dvec3> normal(rims.count, glm::dvec3(0.0));
  for (const glm::uvec2& e : rims.edges) {
    const glm::dvec3 c = centroid[rims.rimOf[e.x]];
    normal[rims.rimOf[e.x]] += glm::cross(mesh.positions[e.x] - c, mesh.positions[e.y] - c);
  }
  // How far each rim leaves its fan's plane.
  std::vector<double> offPlane(rims.count, 0.0);
  for (const glm::uvec2& e : rims.edges) {
    const uint32_t r = rims.rimOf[e.x];
    const double length = glm::length(normal[r]);
    const glm::dvec3 away = mesh.positions[e.x] - centroid[r];
    offPlane[r] =
        std::max(offPlane[r], length > 0.0 ? std::abs(glm::dot(away, normal[r] / length)) : glm::length(away));
  }
  // Which rims get a fan (the others' films, if they leave the band, make it
  // widen, pipeline/denoise.cpp):
  // - A film at least as large as the fan's vector area (half the Newell
  //   normal's length; equal for a planar rim): a smaller one lies within
  //   the band anyway. A T-junction's "rim" (a long edge one way, the short
  //   ones beside it back) encloses nothing, and its fan would only fill a
  //   solid with bricks (a cube with T-junctions on every edge: the whole
  //   grid).
  // - A rim near its plane: one that leaves it by more than the radius of a
  //   disk of its area (T-junctions joined to a hole through a corner: an
  //   open box's, the box's height) is no hole's rim alone.
  // - A film through the fan's centre: the winding number there is near 1/2
  //   on a hole's film, and near 0 or 1 where the "rim" is a crack between
  //   pieces that nearly meet (a sphere cut in two, 1e-7 apart: a fan across
  //   the whole body).
  std::vector<uint8_t> fanned(rims.count, 0);
  for (uint32_t r = 0; r < rims.count; ++r) {
    const double area = 0.5 * glm::length(normal[r]);
    if (!(area > leastArea) || offPlane[r] > std::sqrt(area / std::acos(-1.0))) continue;
    if (windingAt && std::abs(windingAt(centroid[r]) - 0.5) > 0.25) continue;
    fanned[r] = 1;
    fans.farthestOffPlane = std::max(fans.farthestOffPlane, offPlane[r]);
  }
  // The fans' own vertices: the rim's, then one centroid a rim.
  std::vector<uint32_t> vertexOf(mesh.positions.size(), UINT32_MAX);
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (rims.onRim[v] && fanned[rims.rimOf[v]]) {
      vertexOf[v] = uint32_t(fans.mesh.positions.size());
      fans.mesh.positions.push_back(mesh.positions[v]);
    }
  const auto firstCentroid = uint32_t(fans.mesh.positions.size());
  fans.mesh.positions.insert(fans.mesh.positions.end(), centroid.begin(), centroid.end());
  for (const glm::uvec2& e : rims.edges) {
    const uint32_t r = rims.rimOf[e.x];
    // Run back, as the triangle that would close the hole runs the edge.
    if (fanned[r]) fans.mesh.triangles.emplace_back(vertexOf[e.y], vertexOf[e.x], firstCentroid + r);
  }
  if (fans.mesh.triangles.empty()) fans.mesh.positions.clear();
  return fans;
}

}  // namespace lbmshape
