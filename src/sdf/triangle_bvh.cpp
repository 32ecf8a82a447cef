#include "lbmshape/sdf/triangle_bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>

#include "lbmshape/core/error.hpp"
#include "lbmshape/sdf/point_triangle.hpp"

namespace lbmshape {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr uint32_t kLeafSize = 4;
constexpr int kBins = 16;
// Past this depth splits fall back to the object median, which halves the
// count: the tree stays shallower than kSahDepth + 32 < kMaxDepth whatever
// the input, however unevenly the area heuristic splits it.
constexpr int kSahDepth = 48;

struct Box {
  glm::dvec3 lo{kInfinity}, hi{-kInfinity};
  void grow(const glm::dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
  void grow(const Box& b) { lo = glm::min(lo, b.lo), hi = glm::max(hi, b.hi); }
  double halfArea() const
  {
    const glm::dvec3 s = glm::max(hi - lo, glm::dvec3(0.0));
    return s.x * s.y + s.y * s.z + s.z * s.x;
  }
};

inline double boxDistance2(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi)
{
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max(std::max(lo[a] - p[a], p[a] - hi[a]), 0.0);
    sum += d * d;
  }
  return sum;
}

// Binned surface area heuristic (Wald 2007) over the triangles' centroids:
// returns the split position in [begin, end) after partitioning `order`,
// or begin when no bin boundary separates the centroids.
uint32_t sahSplit(std::vector<uint32_t>& order, uint32_t begin, uint32_t end, const std::vector<glm::dvec3>& centroid,
                  const std::vector<Box>& triangleBox, const Box& centroids)
{
  double bestCost = kInfinity;
  int bestAxis = -1, bestBin = 0;
  const glm::dvec3 extent = centroids.hi - centroids.lo;
  for (int axis = 0; axis < 3; ++axis) {
    if (!(extent[axis] > 0.0)) continue;
    const double scale = kBins / extent[axis];
    std::array<Box, kBins> boxes;
    std::array<uint32_t, kBins> counts{};
    for (uint32_t i = begin; i < end; ++i) {
      const uint32_t t = order[i];
      const int bin = std::min(kBins - 1, int((centroid[t][axis] - centroids.lo[axis]) * scale));
      boxes[bin].grow(triangleBox[t]);
      ++counts[bin];
    }
    std::array<double, kBins> rightCost{};
    Box right;
    uint32_t rightCount = 0;
    for (int b = kBins - 1; b > 0; --b) {
      right.grow(boxes[b]);
      rightCount += counts[b];
      rightCost[b] = rightCount ? right.halfArea() * rightCount : 0.0;
    }
    Box left;
    uint32_t leftCount = 0;
    for (int b = 1; b < kBins; ++b) {
      left.grow(boxes[b - 1]);
      leftCount += counts[b - 1];
      if (leftCount == 0 || leftCount == end - begin) continue;
      const double cost = left.halfArea() * leftCount + rightCost[b];
      if (cost < bestCost) bestCost = cost, bestAxis = axis, bestBin = b;
    }
  }
  if (bestAxis < 0) return begin;
  const double scale = kBins / extent[bestAxis];
  auto middle = std::partition(order.begin() + begin, order.begin() + end, [&](uint32_t t) {
    return std::min(kBins - 1, int((centroid[t][bestAxis] - centroids.lo[bestAxis]) * scale)) < bestBin;
  });
  return uint32_t(middle - order.begin());
}

uint32_t medianSplit(std::vector<uint32_t>& order, uint32_t begin, uint32_t end,
                     const std::vector<glm::dvec3>& centroid, const Box& centroids)
{
  const glm::dvec3 extent = centroids.hi - centroids.lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                   [&](uint32_t a, uint32_t b) { return centroid[a][axis] < centroid[b][axis]; });
  return middle;
}

// Builds the hierarchy over order[begin, end) (which it reorders) as an
// array laid out depth first: a node's first child follows it, so the common
// descent reads memory forward, and an inner node records where its second
// child starts. Indices are local to the array returned.
struct Builder {
  const std::vector<glm::dvec3>& centroid;
  const std::vector<Box>& triangleBox;
  std::vector<uint32_t>& order;

  // Splits [begin, end) and returns the node over it; sets middle (or to
  // begin for a leaf).
  template <class NodeT>
  NodeT split(uint32_t begin, uint32_t end, int depth, uint32_t& middle) const
  {
    Box bounds, centroids;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.grow(triangleBox[order[i]]);
      centroids.grow(centroid[order[i]]);
    }
    middle = begin;
    if (end - begin <= kLeafSize) return NodeT{bounds.lo, bounds.hi, begin, end - begin};
    if (depth < kSahDepth) middle = sahSplit(order, begin, end, centroid, triangleBox, centroids);
    if (middle == begin || middle == end) middle = medianSplit(order, begin, end, centroid, centroids);
    return NodeT{bounds.lo, bounds.hi, 0, 0};
  }

  template <class NodeT>
  std::vector<NodeT> layOut(uint32_t begin, uint32_t end, int depth) const
  {
    // A task knows its parent when it is a second child, whose index the
    // parent learns only once the first child's subtree is laid out.
    struct Task {
      uint32_t begin, end, parent;
      int depth;
    };
    std::vector<NodeT> nodes;
    nodes.reserve(2 * ((end - begin) / kLeafSize + 1));
    std::vector<Task> tasks{{begin, end, kNoParent, depth}};
    while (!tasks.empty()) {
      const Task task = tasks.back();
      tasks.pop_back();
      const uint32_t index = uint32_t(nodes.size());
      if (task.parent != kNoParent) nodes[task.parent].first = index;
      uint32_t middle;
      nodes.push_back(split<NodeT>(task.begin, task.end, task.depth, middle));
      if (middle == task.begin) continue;
      tasks.push_back({middle, task.end, index, task.depth + 1});
      tasks.push_back({task.begin, middle, kNoParent, task.depth + 1});
    }
    return nodes;
  }

  template <class NodeT>
  std::vector<NodeT> layOutParallel(uint32_t begin, uint32_t end, int depth) const
  {
    if (depth >= kTaskDepth || end - begin < kTaskSize) return layOut<NodeT>(begin, end, depth);
    uint32_t middle;
    std::vector<NodeT> nodes{split<NodeT>(begin, end, depth, middle)};
    if (middle == begin) return nodes;
    std::vector<NodeT> first, second;
#pragma omp task shared(first)
    first = layOutParallel<NodeT>(begin, middle, depth + 1);
#pragma omp task shared(second)
    second = layOutParallel<NodeT>(middle, end, depth + 1);
#pragma omp taskwait
    nodes[0].first = uint32_t(1 + first.size());
    for (const std::vector<NodeT>* part : {&first, &second}) {
      const uint32_t offset = uint32_t(nodes.size());
      for (NodeT node : *part) {
        if (node.count == 0) node.first += offset;
        nodes.push_back(node);
      }
    }
    return nodes;
  }

  static constexpr uint32_t kNoParent = std::numeric_limits<uint32_t>::max();
  static constexpr int kTaskDepth = 3;  // up to 8 subtrees
  static constexpr uint32_t kTaskSize = 4096;
};

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh, Queries queries)
{
  triangles_.reserve(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    Triangle tri;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[t][k];
      if (v >= mesh.positions.size()) {
        std::ostringstream m;
        m << "triangle " << t << " uses vertex " << v << " but the mesh has " << mesh.positions.size() << " vertices";
        throw InputError(m.str());
      }
      const glm::dvec3& p = mesh.positions[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        std::ostringstream m;
        m << "vertex " << v << " (used by triangle " << t << ") has a non-finite position";
        throw InputError(m.str());
      }
      (k == 0 ? tri.a : k == 1 ? tri.b : tri.c) = p;
    }
    triangles_.push_back(tri);
  }
  if (triangles_.size() >= kNoTriangle) throw InputError("the mesh has too many triangles");
  build();
  if (queries == Queries::ClosestAndWinding) buildExpansions();
}

void TriangleBvh::build()
{
  const uint32_t n = uint32_t(triangles_.size());
  if (n == 0) return;
  std::vector<glm::dvec3> centroid(n);
  std::vector<Box> triangleBox(n);
  for (uint32_t t = 0; t < n; ++t) {
    const Triangle& tri = triangles_[t];
    centroid[t] = (tri.a + tri.b + tri.c) / 3.0;
    triangleBox[t].grow(tri.a), triangleBox[t].grow(tri.b), triangleBox[t].grow(tri.c);
  }
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  const Builder builder{centroid, triangleBox, order};
  // The top levels split into tasks, each laying out a subtree in its own
  // array; the arrays are then spliced (so the result is the same for any
  // number of threads).
#pragma omp parallel
#pragma omp single
  nodes_ = builder.layOutParallel<Node>(0, n, 0);
  std::vector<Triangle> sorted(n);
  meshIndex_ = order;
  slotOf_.assign(n, 0);
  for (uint32_t slot = 0; slot < n; ++slot) {
    sorted[slot] = triangles_[order[slot]];
    slotOf_[order[slot]] = slot;
  }
  triangles_.swap(sorted);
}

TriangleBvh::Closest TriangleBvh::closest(const glm::dvec3& p) const { return closest(p, kInfinity); }

TriangleBvh::Closest TriangleBvh::closest(const glm::dvec3& p, double upperBound) const
{
  Closest best{kInfinity, p, kNoTriangle};
  if (nodes_.empty() || !(upperBound >= 0.0)) return best;
  // A triangle exactly at upperBound must not be lost to rounding in the
  // caller's computation of the bound or in ours of the distance.
  const double inflated = upperBound * (1.0 + 1e-12) + 1e-300;
  double best2 = inflated * inflated;
  uint32_t bestSlot = kNoTriangle;

  struct Entry {
    uint32_t node;
    double distance2;
  };
  std::array<Entry, kMaxDepth + 2> stack;
  int top = 0;
  stack[top++] = {0, boxDistance2(p, nodes_[0].lo, nodes_[0].hi)};
  while (top > 0) {
    const Entry entry = stack[--top];
    if (entry.distance2 > best2) continue;
    const Node& node = nodes_[entry.node];
    if (node.count > 0) {
      for (uint32_t slot = node.first; slot < node.first + node.count; ++slot) {
        const Triangle& t = triangles_[slot];
        const glm::dvec3 q = closestPointOnTriangle(p, t.a, t.b, t.c);
        const double d2 = glm::dot(q - p, q - p);
        if (d2 < best2 || (bestSlot == kNoTriangle && d2 <= best2)) best2 = d2, bestSlot = slot, best.point = q;
      }
      continue;
    }
    // Visit the nearer child first: it usually holds the answer, and a
    // small best2 early prunes most of the other one.
    const uint32_t left = entry.node + 1, right = node.first;
    const double dl = boxDistance2(p, nodes_[left].lo, nodes_[left].hi);
    const double dr = boxDistance2(p, nodes_[right].lo, nodes_[right].hi);
    const Entry near = dl <= dr ? Entry{left, dl} : Entry{right, dr};
    const Entry far = dl <= dr ? Entry{right, dr} : Entry{left, dl};
    if (far.distance2 <= best2) stack[top++] = far;
    if (near.distance2 <= best2) stack[top++] = near;
  }
  if (bestSlot == kNoTriangle) return best;
  best.distance = std::sqrt(best2);
  best.triangle = meshIndex_[bestSlot];
  return best;
}

TriangleBvh::Closest TriangleBvh::closestOnTriangle(const glm::dvec3& p, uint32_t triangle) const
{
  const Triangle& t = triangles_[slotOf_.at(triangle)];
  const glm::dvec3 q = closestPointOnTriangle(p, t.a, t.b, t.c);
  return {glm::length(q - p), q, triangle};
}

}  // namespace lbmshape
