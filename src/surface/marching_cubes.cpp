// Two passes over z. The first counts, per grid plane, the cut edges it owns
// (the x and y edges in the plane and the z edges up to the next plane) and,
// per layer of cubes, the triangles; prefix sums of the counts give every
// vertex and triangle its final index. The second pass runs over chunks of
// layers in parallel and writes vertices and triangles straight to those
// indices, so no merge is needed and the output is the same for any number
// of threads or chunks. A chunk finds the indices of the vertices on its top
// plane by counting the same way, but leaves writing them to their owner.
// Both passes walk the inside bitmask a word at a time, so they spend their
// time where the surface is.
#include "lbmshape/surface/marching_cubes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <omp.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/surface/case_triangulation.hpp"
#include "lbmshape/surface/cube_cases.hpp"
#include "lbmshape/surface/edge_vertex.hpp"
#include "lbmshape/surface/inside_mask.hpp"
#include "lbmshape/surface/loop_triangulation.hpp"

namespace lbmshape {
namespace {

struct Grid {
  const float* values;
  int nx, ny, nz;
  float iso;

  size_t index(int x, int y, int z) const { return size_t(x) + size_t(nx) * (size_t(y) + size_t(ny) * size_t(z)); }
  float at(int x, int y, int z) const { return values[index(x, y, z)]; }

  // Where along the edge from sample a to sample b the field crosses iso.
  double crossing(float a, float b) const { return edge_vertex::crossing(a, b, iso); }

  int caseIndex(int x, int y, int z) const
  {
    const size_t i = index(x, y, z), sy = size_t(nx), sz = size_t(nx) * size_t(ny);
    const float* v = values + i;
    return int(v[0] > iso) | int(v[1] > iso) << 1 | int(v[sy] > iso) << 2 | int(v[sy + 1] > iso) << 3 |
           int(v[sz] > iso) << 4 | int(v[sz + 1] > iso) << 5 | int(v[sz + sy] > iso) << 6 |
           int(v[sz + sy + 1] > iso) << 7;
  }

  glm::dvec3 gradient(int x, int y, int z) const
  {
    return edge_vertex::gradient([this](int a, int b, int c) { return at(a, b, c); }, Extent3{nx, ny, nz}, x, y, z);
  }
};

// Word w of the cut-edge and mixed-cube masks of row (y, z), from the
// inside bits of the row and its neighbours.
struct RowBits {
  const InsideMask& mask;
  int nx;

  uint64_t xCuts(const uint64_t* row, int w) const
  {
    return (row[w] ^ mask.next(row, w)) & InsideMask::below(w, nx - 1);
  }
  // Edges between this row and `other` (the next row in y or in z).
  uint64_t crossCuts(const uint64_t* row, const uint64_t* other, int w) const
  {
    return (row[w] ^ other[w]) & InsideMask::below(w, nx);
  }
  // Cubes with corners in rows a, b (next y), c (next z), d (next y and z)
  // that have both inside and outside corners.
  uint64_t mixedCubes(const uint64_t* a, const uint64_t* b, const uint64_t* c, const uint64_t* d, int w) const
  {
    const uint64_t any = a[w] | b[w] | c[w] | d[w];
    const uint64_t all = a[w] & b[w] & c[w] & d[w];
    const uint64_t anyNext = mask.next(a, w) | mask.next(b, w) | mask.next(c, w) | mask.next(d, w);
    const uint64_t allNext = mask.next(a, w) & mask.next(b, w) & mask.next(c, w) & mask.next(d, w);
    return (any | anyNext) & ~(all & allNext) & InsideMask::below(w, nx - 1);
  }
};

struct PlaneCounts {
  std::vector<uint64_t> planeVertices;  // cut x and y edges in plane z
  std::vector<uint64_t> riserVertices;  // cut z edges from plane z to z + 1
  std::vector<uint64_t> triangles;      // triangles of the cubes between z and z + 1
};

PlaneCounts countPlanes(const Grid& g, const InsideMask& mask)
{
  const auto& cases = cube::cubeCases();
  const RowBits bits{mask, g.nx};
  PlaneCounts counts{std::vector<uint64_t>(g.nz), std::vector<uint64_t>(g.nz), std::vector<uint64_t>(g.nz)};
#pragma omp parallel for schedule(dynamic, 1)
  for (int z = 0; z < g.nz; ++z) {
    uint64_t plane = 0, riser = 0, triangles = 0;
    for (int y = 0; y < g.ny; ++y) {
      const uint64_t* a = mask.row(y, z);
      const uint64_t* b = y + 1 < g.ny ? mask.row(y + 1, z) : nullptr;
      const uint64_t* c = z + 1 < g.nz ? mask.row(y, z + 1) : nullptr;
      for (int w = 0; w < mask.words(); ++w) {
        plane += std::popcount(bits.xCuts(a, w));
        if (b) plane += std::popcount(bits.crossCuts(a, b, w));
        if (c) riser += std::popcount(bits.crossCuts(a, c, w));
        if (b && c)
          InsideMask::forEachBit(bits.mixedCubes(a, b, c, mask.row(y + 1, z + 1), w), w,
                                 [&](int x) { triangles += cases[g.caseIndex(x, y, z)].triangleCount(); });
      }
    }
    counts.planeVertices[z] = plane;
    counts.riserVertices[z] = riser;
    counts.triangles[z] = triangles;
  }
  return counts;
}

// Where each of the 12 cube edges finds its vertex index: in the x or y edge
// index of the lower (0) or upper (1) plane, or among the z edges, at an
// offset (dx, dy) from the cube's lower corner.
struct EdgeSlot {
  enum Kind : uint8_t { X0, X1, Y0, Y1, Z } kind;
  uint8_t dx, dy;
};

std::array<EdgeSlot, 12> makeEdgeSlots()
{
  std::array<EdgeSlot, 12> slots{};
  for (int e = 0; e < 12; ++e) {
    const int k = e & 3, lowBit = k & 1, highBit = k >> 1;
    switch (e / 4) {
    case 0: slots[e] = {highBit ? EdgeSlot::X1 : EdgeSlot::X0, 0, uint8_t(lowBit)}; break;
    case 1: slots[e] = {highBit ? EdgeSlot::Y1 : EdgeSlot::Y0, uint8_t(lowBit), 0}; break;
    default: slots[e] = {EdgeSlot::Z, uint8_t(lowBit), uint8_t(highBit)}; break;
    }
  }
  return slots;
}

class SlabWriter {
public:
  SlabWriter(const Grid& g, const InsideMask& mask, const GridFrame& frame, const std::vector<uint64_t>& vertexBase,
             const std::vector<uint64_t>& planeVertices, const std::vector<uint64_t>& triangleBase, TriangleMesh& mesh)
      : g_(g), mask_(mask), bits_{mask, g.nx}, frame_(frame), vertexBase_(vertexBase), planeVertices_(planeVertices),
        triangleBase_(triangleBase), mesh_(mesh), planeSize_(size_t(g.nx) * g.ny), slots_(makeEdgeSlots())
  {
    for (auto& buffer : planes_) buffer.resize(planeSize_);
    risers_.resize(planeSize_);
  }

  // Cubes of layers [z0, z1); writes the vertices that planes z0 .. z1 - 1 own
  // (and the top plane's, when z1 is the last plane).
  void run(int z0, int z1)
  {
    int lower = 0;
    indexPlane(z0, planes_[lower], true);
    for (int z = z0; z < z1; ++z) {
      indexRisers(z);
      indexPlane(z + 1, planes_[1 - lower], z + 1 < z1 || z + 1 == g_.nz - 1);
      triangulateLayer(z, planes_[lower], planes_[1 - lower]);
      lower = 1 - lower;
    }
  }

private:
  struct PlaneIndex {
    std::vector<uint32_t> x, y;
    void resize(size_t n) { x.resize(n), y.resize(n); }
  };

  void emitVertex(uint64_t index, int x, int y, int z, int axis)
  {
    int end[3] = {x, y, z};
    ++end[axis];
    const float a = g_.at(x, y, z), b = g_.at(end[0], end[1], end[2]);
    const double t = g_.crossing(a, b);
    glm::dvec3 grid(x, y, z);
    grid[axis] += t;
    mesh_.positions[index] = frame_.toWorld(grid);
    mesh_.normals[index] =
        edge_vertex::normal(g_.gradient(x, y, z), g_.gradient(end[0], end[1], end[2]), t, axis, a > g_.iso);
  }

  // Numbers the cut edges of plane z in the order countPlanes counted them:
  // x edges row by row, then y edges row by row.
  void indexPlane(int z, PlaneIndex& index, bool write)
  {
    uint64_t next = vertexBase_[z];
    for (int y = 0; y < g_.ny; ++y) {
      const uint64_t* row = mask_.row(y, z);
      for (int w = 0; w < mask_.words(); ++w)
        InsideMask::forEachBit(bits_.xCuts(row, w), w, [&](int x) {
          if (write) emitVertex(next, x, y, z, 0);
          index.x[size_t(y) * g_.nx + x] = uint32_t(next++);
        });
    }
    for (int y = 0; y + 1 < g_.ny; ++y) {
      const uint64_t *row = mask_.row(y, z), *other = mask_.row(y + 1, z);
      for (int w = 0; w < mask_.words(); ++w)
        InsideMask::forEachBit(bits_.crossCuts(row, other, w), w, [&](int x) {
          if (write) emitVertex(next, x, y, z, 1);
          index.y[size_t(y) * g_.nx + x] = uint32_t(next++);
        });
    }
  }

  void indexRisers(int z)
  {
    uint64_t next = vertexBase_[z] + planeVertices_[z];
    for (int y = 0; y < g_.ny; ++y) {
      const uint64_t *row = mask_.row(y, z), *other = mask_.row(y, z + 1);
      for (int w = 0; w < mask_.words(); ++w)
        InsideMask::forEachBit(bits_.crossCuts(row, other, w), w, [&](int x) {
          emitVertex(next, x, y, z, 2);
          risers_[size_t(y) * g_.nx + x] = uint32_t(next++);
        });
    }
  }

  uint32_t vertexOf(int edge, int x, int y, const PlaneIndex& lower, const PlaneIndex& upper) const
  {
    const EdgeSlot s = slots_[edge];
    const size_t i = size_t(y + s.dy) * g_.nx + (x + s.dx);
    switch (s.kind) {
    case EdgeSlot::X0: return lower.x[i];
    case EdgeSlot::X1: return upper.x[i];
    case EdgeSlot::Y0: return lower.y[i];
    case EdgeSlot::Y1: return upper.y[i];
    default: return risers_[i];
    }
  }

  // The cube-local position of the vertex on a cube edge, computed exactly as
  // emitVertex does, so the triangulation sees the real geometry.
  glm::dvec3 localPoint(int edge, int x, int y, int z) const
  {
    const cube::Edge& e = cube::edges()[edge];
    glm::dvec3 p(cube::cornerOffset(e.lower, 0), cube::cornerOffset(e.lower, 1), cube::cornerOffset(e.lower, 2));
    const float a = g_.at(x + int(p.x), y + int(p.y), z + int(p.z));
    const float b = g_.at(x + cube::cornerOffset(e.upper, 0), y + cube::cornerOffset(e.upper, 1),
                          z + cube::cornerOffset(e.upper, 2));
    p[e.axis] += g_.crossing(a, b);
    return p;
  }

  void triangulateLayer(int z, const PlaneIndex& lower, const PlaneIndex& upper)
  {
    uint64_t next = triangleBase_[z];
    for (int y = 0; y + 1 < g_.ny; ++y) {
      const uint64_t *a = mask_.row(y, z), *b = mask_.row(y + 1, z), *c = mask_.row(y, z + 1),
                     *d = mask_.row(y + 1, z + 1);
      for (int w = 0; w < mask_.words(); ++w)
        InsideMask::forEachBit(bits_.mixedCubes(a, b, c, d, w), w,
                               [&](int x) { triangulateCube(x, y, z, lower, upper, next); });
    }
  }

  void triangulateCube(int x, int y, int z, const PlaneIndex& lower, const PlaneIndex& upper, uint64_t& next)
  {
    const cube::CubeCase& c = cube::cubeCases()[g_.caseIndex(x, y, z)];
    std::array<uint32_t, 12> vertex;
    for (int i = 0; i < c.edgeCount; ++i) vertex[i] = vertexOf(c.edges[i], x, y, lower, upper);
    triangulateCubeCase(
        c, [&](int edge) { return localPoint(edge, x, y, z); },
        [&](int i, int j, int k) { mesh_.triangles[next++] = glm::uvec3(vertex[i], vertex[j], vertex[k]); });
  }

  const Grid& g_;
  const InsideMask& mask_;
  RowBits bits_;
  const GridFrame& frame_;
  const std::vector<uint64_t>& vertexBase_;
  const std::vector<uint64_t>& planeVertices_;
  const std::vector<uint64_t>& triangleBase_;
  TriangleMesh& mesh_;
  size_t planeSize_;
  std::array<EdgeSlot, 12> slots_;
  PlaneIndex planes_[2];
  std::vector<uint32_t> risers_;
};

std::vector<uint64_t> exclusivePrefixSum(const std::vector<uint64_t>& a, const std::vector<uint64_t>& b)
{
  std::vector<uint64_t> base(a.size() + 1, 0);
  for (size_t i = 0; i < a.size(); ++i) base[i + 1] = base[i] + a[i] + (b.empty() ? 0 : b[i]);
  return base;
}

}  // namespace

TriangleMesh extractSurface(const Volume& field, const GridFrame& frame, float isovalue)
{
  if (!(frame.extent == field.extent()))
    throw std::invalid_argument("the field is " + field.extent().toString() + " but its frame is " +
                                frame.extent.toString());
  if (!std::isfinite(isovalue)) throw UsageError("the iso value must be a finite number");
  const Extent3 e = field.extent();
  TriangleMesh mesh;
  if (e.nx < 2 || e.ny < 2 || e.nz < 2) return mesh;

  const Grid g{field.data(), e.nx, e.ny, e.nz, isovalue};
  const InsideMask mask(field, isovalue);
  const PlaneCounts counts = countPlanes(g, mask);
  const std::vector<uint64_t> vertexBase = exclusivePrefixSum(counts.planeVertices, counts.riserVertices);
  const std::vector<uint64_t> triangleBase = exclusivePrefixSum(counts.triangles, {});
  if (vertexBase.back() >= std::numeric_limits<uint32_t>::max())
    throw UsageError("the surface has more than 4 billion vertices; use a coarser grid");
  mesh.positions.resize(vertexBase.back());
  mesh.normals.resize(vertexBase.back());
  mesh.triangles.resize(triangleBase.back());

  // Chunks of layers; each thread keeps its plane buffers across its chunks.
  const int layers = e.nz - 1;
  const int chunks = std::min(layers, 4 * omp_get_max_threads());
#pragma omp parallel
  {
    SlabWriter writer(g, mask, frame, vertexBase, counts.planeVertices, triangleBase, mesh);
#pragma omp for schedule(dynamic, 1)
    for (int c = 0; c < chunks; ++c)
      writer.run(int(int64_t(layers) * c / chunks), int(int64_t(layers) * (c + 1) / chunks));
  }
  return mesh;
}

}  // namespace lbmshape
