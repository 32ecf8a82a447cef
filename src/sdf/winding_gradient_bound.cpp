#include "lbmshape/sdf/winding_gradient_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <unordered_map>

#include "lbmshape/core/error.hpp"

namespace lbmshape {
namespace {

// Named apart from triangle_bvh.cpp's constants: the two share a unity file.
constexpr double kUnbounded = std::numeric_limits<double>::infinity();
constexpr uint32_t kEdgesPerLeaf = 4;

struct PositionHash {
  size_t operator()(const glm::dvec3& p) const
  {
    uint64_t bits[3];
    std::memcpy(bits, &p, sizeof bits);
    uint64_t h = 1469598103934665603ull;
    for (uint64_t b : bits) h = (h ^ b) * 1099511628211ull ^ (h >> 29);
    return size_t(h);
  }
};

double boxBoxDistance2(const glm::dvec3& alo, const glm::dvec3& ahi, const glm::dvec3& blo, const glm::dvec3& bhi)
{
  const glm::dvec3 gap = glm::max(glm::max(blo - ahi, alo - bhi), glm::dvec3(0.0));
  return glm::dot(gap, gap);
}

}  // namespace

WindingGradientBound::WindingGradientBound(const TriangleMesh& mesh)
{
  // Weld by exact position (+0.0 and -0.0 are one point), so that soups
  // with one vertex per corner still cancel their shared edges.
  std::unordered_map<glm::dvec3, uint32_t, PositionHash> welded;
  welded.reserve(mesh.positions.size());
  std::vector<uint32_t> id(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::dvec3 p = mesh.positions[v] + glm::dvec3(0.0);
    id[v] = welded.try_emplace(p, uint32_t(welded.size())).first->second;
  }
  // Each directed edge a->b counts +1 on key (min, max) when a < b and -1
  // otherwise; what is left after summing is the boundary.
  std::vector<std::pair<uint64_t, int>> keyed;
  keyed.reserve(3 * mesh.triangles.size());
  for (const glm::uvec3& t : mesh.triangles) {
    if (t.x >= id.size() || t.y >= id.size() || t.z >= id.size())
      throw InputError("a triangle uses a vertex index past the mesh's vertices");
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = id[t[k]], b = id[t[(k + 1) % 3]];
      if (a == b) continue;
      keyed.emplace_back(uint64_t(std::min(a, b)) << 32 | std::max(a, b), a < b ? 1 : -1);
    }
  }
  std::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<uint32_t> representative(welded.size());
  for (size_t v = mesh.positions.size(); v-- > 0;) representative[id[v]] = uint32_t(v);
  for (size_t i = 0; i < keyed.size();) {
    size_t j = i;
    int net = 0;
    for (; j < keyed.size() && keyed[j].first == keyed[i].first; ++j) net += keyed[j].second;
    if (net != 0) {
      const glm::dvec3& a = mesh.positions[representative[keyed[i].first >> 32]];
      const glm::dvec3& b = mesh.positions[representative[keyed[i].first & 0xffffffffu]];
      edges_.push_back(Edge{a, b, std::abs(net) * glm::length(b - a)});
      openEdges_ += size_t(std::abs(net));
    }
    i = j;
  }
  build();
}

void WindingGradientBound::build()
{
  if (edges_.empty()) return;
  struct Task {
    uint32_t begin, end, parent;
  };
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  std::vector<Task> tasks{{0, uint32_t(edges_.size()), kNone}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    const uint32_t index = uint32_t(nodes_.size());
    if (task.parent != kNone) nodes_[task.parent].first = index;
    Node node{glm::dvec3(kUnbounded), glm::dvec3(-kUnbounded), 0.0, task.begin, task.end - task.begin};
    for (uint32_t i = task.begin; i < task.end; ++i) {
      node.lo = glm::min(node.lo, glm::min(edges_[i].a, edges_[i].b));
      node.hi = glm::max(node.hi, glm::max(edges_[i].a, edges_[i].b));
      node.weight += edges_[i].weight;
    }
    nodes_.push_back(node);
    if (node.count <= kEdgesPerLeaf) continue;
    // Median split on the longest side: halves the count, so the depth is logarithmic.
    const glm::dvec3 size = node.hi - node.lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const uint32_t middle = task.begin + node.count / 2;
    std::nth_element(edges_.begin() + task.begin, edges_.begin() + middle, edges_.begin() + task.end,
                     [axis](const Edge& x, const Edge& y) { return x.a[axis] + x.b[axis] < y.a[axis] + y.b[axis]; });
    nodes_[index].count = 0;
    tasks.push_back({middle, task.end, index});
    tasks.push_back({task.begin, middle, kNone});
  }
}

double WindingGradientBound::over(const glm::dvec3& lo, const glm::dvec3& hi, double limit) const
{
  if (nodes_.empty()) return 0.0;
  const double scale = 1.0 / (4.0 * std::numbers::pi);
  double sum = 0.0;
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    const uint32_t index = stack.back();
    stack.pop_back();
    const double gap2 = boxBoxDistance2(lo, hi, node.lo, node.hi);
    const glm::dvec3 size = node.hi - node.lo;
    // A node far from the box compared with its own size is summed as a
    // whole: its total length at its nearest distance. Nearer nodes are
    // opened to tighten the bound.
    if (gap2 > 0.0 && glm::dot(size, size) <= gap2) {
      sum += scale * node.weight / gap2;
    } else if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        const Edge& e = edges_[i];
        const double d2 = boxBoxDistance2(lo, hi, glm::min(e.a, e.b), glm::max(e.a, e.b));
        if (!(d2 > 0.0)) return kUnbounded;
        sum += scale * e.weight / d2;
      }
    } else {
      stack.push_back(node.first);
      stack.push_back(index + 1);
    }
    if (sum > limit) return sum;
  }
  return sum;
}

}  // namespace lbmshape
