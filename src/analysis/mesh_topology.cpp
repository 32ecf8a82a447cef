// Edges and fans are found with bucket sorts by vertex (linear time, no hash
// tables), so a million triangles take a fraction of a second. Every count is
// an integer and the sums of area and volume run in fixed chunks added in a
// fixed order, so the result does not depend on the number of threads.
#include "lbmshape/analysis/mesh_topology.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/ordered_sum.hpp"

namespace lbmshape {
namespace {

bool isDegenerate(const glm::uvec3& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

void checkIndices(const TriangleMesh& mesh)
{
  const size_t n = mesh.positions.size();
  for (size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles[i][k] >= n) {
        std::ostringstream message;
        message << "triangle " << i << " refers to vertex " << mesh.triangles[i][k] << " but the mesh has " << n
                << " vertices";
        throw InputError(message.str());
      }
}

// Compressed lists: the items of key k are items[start[k] .. start[k + 1]).
template <class Item>
struct Buckets {
  std::vector<uint32_t> start;
  std::vector<Item> items;
};

// Half-edges of the non-degenerate triangles, bucketed by their smaller
// vertex; each item holds the larger vertex and whether the triangle runs the
// edge from smaller to larger.
Buckets<std::pair<uint32_t, bool>> halfEdgesByLowerVertex(const TriangleMesh& mesh)
{
  Buckets<std::pair<uint32_t, bool>> b;
  b.start.assign(mesh.positions.size() + 1, 0);
  for (const auto& t : mesh.triangles)
    if (!isDegenerate(t))
      for (int k = 0; k < 3; ++k) ++b.start[std::min(t[k], t[(k + 1) % 3]) + 1];
  std::partial_sum(b.start.begin(), b.start.end(), b.start.begin());
  b.items.resize(b.start.back());
  std::vector<uint32_t> fill(b.start.begin(), b.start.end() - 1);
  for (const auto& t : mesh.triangles)
    if (!isDegenerate(t))
      for (int k = 0; k < 3; ++k) {
        const uint32_t u = t[k], v = t[(k + 1) % 3];
        b.items[fill[std::min(u, v)]++] = {std::max(u, v), u < v};
      }
  return b;
}

Buckets<uint32_t> trianglesByVertex(const TriangleMesh& mesh)
{
  Buckets<uint32_t> b;
  b.start.assign(mesh.positions.size() + 1, 0);
  for (const auto& t : mesh.triangles)
    if (!isDegenerate(t))
      for (int k = 0; k < 3; ++k) ++b.start[t[k] + 1];
  std::partial_sum(b.start.begin(), b.start.end(), b.start.begin());
  b.items.resize(b.start.back());
  std::vector<uint32_t> fill(b.start.begin(), b.start.end() - 1);
  for (size_t i = 0; i < mesh.triangles.size(); ++i)
    if (!isDegenerate(mesh.triangles[i]))
      for (int k = 0; k < 3; ++k) b.items[fill[mesh.triangles[i][k]]++] = uint32_t(i);
  return b;
}

void countEdges(const TriangleMesh& mesh, MeshTopology& result)
{
  auto edges = halfEdgesByLowerVertex(mesh);
  const int64_t vertices = int64_t(edges.start.size()) - 1;
  size_t count = 0, boundary = 0, nonManifold = 0, inconsistent = 0;
  // Each vertex sorts its own bucket: the vertices are independent.
#pragma omp parallel for schedule(dynamic, 4096) reduction(+ : count, boundary, nonManifold, inconsistent)
  for (int64_t v = 0; v < vertices; ++v) {
    auto first = edges.items.begin() + edges.start[v], last = edges.items.begin() + edges.start[v + 1];
    std::sort(first, last);
    while (first != last) {
      auto end = std::find_if(first, last, [&](const auto& h) { return h.first != first->first; });
      const size_t faces = size_t(end - first);
      const size_t forward = size_t(std::count_if(first, end, [](const auto& h) { return h.second; }));
      ++count;
      boundary += faces == 1;
      nonManifold += faces > 2;
      inconsistent += faces == 2 && forward != 1;
      first = end;
    }
  }
  result.edges = count;
  result.boundaryEdges = boundary;
  result.nonManifoldEdges = nonManifold;
  result.inconsistentEdges = inconsistent;
}

// A vertex is manifold when its triangles form one fan: joined to each other
// through the edges they share at the vertex.
size_t countNonManifoldVertices(const TriangleMesh& mesh)
{
  const auto fans = trianglesByVertex(mesh);
  const int64_t n = int64_t(mesh.positions.size());
  size_t bad = 0;
#pragma omp parallel reduction(+ : bad)
  {
    std::vector<std::pair<uint32_t, uint32_t>> spokes;  // (other vertex, local triangle)
    std::vector<uint32_t> parent;
#pragma omp for schedule(dynamic, 4096)
    for (int64_t v = 0; v < n; ++v) {
      const uint32_t begin = fans.start[v], count = fans.start[v + 1] - begin;
      if (count < 2) continue;
      spokes.clear();
      for (uint32_t i = 0; i < count; ++i) {
        const glm::uvec3& t = mesh.triangles[fans.items[begin + i]];
        for (int k = 0; k < 3; ++k)
          if (t[k] != uint32_t(v)) spokes.emplace_back(t[k], i);
      }
      std::sort(spokes.begin(), spokes.end());
      parent.resize(count);
      std::iota(parent.begin(), parent.end(), 0u);
      auto find = [&](uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
      };
      uint32_t fansLeft = count;
      for (size_t i = 1; i < spokes.size(); ++i)
        if (spokes[i].first == spokes[i - 1].first) {
          const uint32_t a = find(spokes[i].second), b = find(spokes[i - 1].second);
          if (a != b) {
            parent[a] = b;
            --fansLeft;
          }
        }
      bad += fansLeft > 1;
    }
  }
  return bad;
}

size_t countComponents(const TriangleMesh& mesh, std::vector<bool>& used)
{
  std::vector<uint32_t> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = true;
      const uint32_t a = find(t[0]), b = find(t[k]);
      if (a != b) parent[b] = a;
    }
  size_t components = 0;
  for (size_t v = 0; v < parent.size(); ++v) components += used[v] && find(uint32_t(v)) == v;
  return components;
}

}  // namespace

MeshTopology analyzeTopology(const TriangleMesh& mesh)
{
  checkIndices(mesh);
  MeshTopology result;
  result.vertices = mesh.positions.size();
  result.triangles = mesh.triangles.size();
  for (const auto& t : mesh.triangles) result.degenerateTriangles += isDegenerate(t);

  std::vector<bool> used(mesh.positions.size(), false);
  result.components = countComponents(mesh, used);
  const size_t referenced = size_t(std::count(used.begin(), used.end(), true));
  result.unreferencedVertices = result.vertices - referenced;

  countEdges(mesh, result);
  result.nonManifoldVertices = countNonManifoldVertices(mesh);
  result.consistentlyOriented = result.inconsistentEdges == 0;
  result.closedManifold = result.triangles > 0 && result.boundaryEdges == 0 && result.nonManifoldEdges == 0 &&
                          result.nonManifoldVertices == 0 && result.inconsistentEdges == 0 &&
                          result.degenerateTriangles == 0;
  result.eulerCharacteristic =
      int64_t(referenced) - int64_t(result.edges) + int64_t(result.triangles - result.degenerateTriangles);
  if (result.closedManifold) result.genus = (2 * int64_t(result.components) - result.eulerCharacteristic) / 2;

  const AreaAndVolume sums = areaAndSignedVolume(mesh);
  result.area = sums.area;
  result.signedVolume = sums.signedVolume;
  return result;
}

AreaAndVolume areaAndSignedVolume(const TriangleMesh& mesh)
{
  // Volume about the box centre, so that a mesh far from the origin does not
  // lose its digits to cancellation; the same sums whatever the number of
  // threads (orderedSum).
  const glm::dvec3 centre = bounds(mesh).centre();
  const glm::dvec2 sums = orderedSum<glm::dvec2>(mesh.triangles.size(), [&](size_t i) {
    const glm::uvec3& t = mesh.triangles[i];
    const glm::dvec3 a = mesh.positions[t[0]] - centre, b = mesh.positions[t[1]] - centre,
                     c = mesh.positions[t[2]] - centre;
    return glm::dvec2(0.5 * glm::length(glm::cross(b - a, c - a)), glm::dot(a, glm::cross(b, c)) / 6.0);
  });
  return {sums.x, sums.y};
}

}  // namespace lbmshape
