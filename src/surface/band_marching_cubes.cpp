#include "surface/band_marching_cubes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <parallel/algorithm>

#include "core/error.hpp"
#include "surface/case_triangulation.hpp"
#include "surface/cube_cases.hpp"
#include "surface/edge_vertex.hpp"

namespace lbmshape {
namespace {

// A cut grid edge, named by the grid index of its lower sample and its axis.
using EdgeKey = uint64_t;

struct BrickTriangles {
  std::vector<std::array<EdgeKey, 3>> triangles;
  std::vector<EdgeKey> keys;  // of their corners, sorted, each once
};

class BrickCubes {
public:
  BrickCubes(const BandField& field, float iso) : field_(field), e_(field.extent()), iso_(iso) {}

  // +1 when every stored cell of the slot is above the isovalue, -1 when
  // every one is at or below it, 0 when mixed.
  int8_t sideOf(int32_t slot) const
  {
    const float* v = field_.values().data() + size_t(slot) * brickCells;
    bool above = false, below = false;
    for (int l = 0; l < brickCells; ++l) (v[l] > iso_ ? above : below) = true;
    return above && below ? 0 : above ? 1 : -1;
  }

  void triangulate(int32_t slot, const std::vector<int8_t>& sides, BrickTriangles& out) const
  {
    // The brick's cubes reach one cell into the seven bricks after it along
    // x, y and z: each of the eight is stored (its values) or not (its far
    // value), or beyond the grid, where no cube reads (and which counts as
    // on the brick's own side).
    const BrickSet& bricks = field_.bricks();
    const glm::ivec3 b = bricks.brick(slot);
    std::array<const float*, 8> from{};
    std::array<float, 8> far{};
    std::array<int8_t, 8> sideOfEach;
    sideOfEach.fill(sides[size_t(slot)]);
    for (int k = 1; k < 8; ++k) {
      const glm::ivec3 n = b + glm::ivec3(k & 1, k >> 1 & 1, k >> 2 & 1);
      if (!bricks.bricks().contains(n.x, n.y, n.z)) continue;
      const int32_t s = bricks.slot(n.x, n.y, n.z);
      if (s != noBrick) {
        from[size_t(k)] = field_.values().data() + size_t(s) * brickCells;
        sideOfEach[size_t(k)] = sides[size_t(s)];
      } else {
        far[size_t(k)] = field_.farValue() * field_.farSide(n.x, n.y, n.z);
        sideOfEach[size_t(k)] = far[size_t(k)] > iso_ ? int8_t(1) : int8_t(-1);
      }
    }
    from[0] = field_.values().data() + size_t(slot) * brickCells;
    // When all eight lie wholly on one side, no cube is cut.
    const auto onTheBricksSide = [&](int8_t x) { return x == sideOfEach[0]; };
    if (sideOfEach[0] != 0 && std::all_of(sideOfEach.begin(), sideOfEach.end(), onTheBricksSide)) return;

    // The brick's cells and the layer after it, 9^3 samples, looked up once
    // each instead of once per cube corner.
    constexpr int side = brickEdge + 1;
    std::array<float, side * side * side> sample;
    for (int z = 0; z < side; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
          const int k = (x >> 3) | (y >> 3) << 1 | (z >> 3) << 2;
          sample[size_t(x + side * (y + side * z))] =
              from[size_t(k)] ? from[size_t(k)][cellInBrick(x & 7, y & 7, z & 7)] : far[size_t(k)];
        }

    const glm::ivec3 origin = brickEdge * b;
    const auto& cases = cube::cubeCases();
    std::array<float, 8> corner;
    for (int lz = 0; lz < brickEdge; ++lz)
      for (int ly = 0; ly < brickEdge; ++ly)
        for (int lx = 0; lx < brickEdge; ++lx) {
          const glm::ivec3 c = origin + glm::ivec3(lx, ly, lz);
          if (c.x + 1 >= e_.nx || c.y + 1 >= e_.ny || c.z + 1 >= e_.nz) continue;
          int index = 0;
          for (int k = 0; k < 8; ++k) {
            const int dx = k & 1, dy = k >> 1 & 1, dz = k >> 2 & 1;
            corner[k] = sample[size_t(lx + dx + side * (ly + dy + side * (lz + dz)))];
            index |= int(corner[k] > iso_) << k;
          }
          if (index == 0 || index == 255) continue;
          triangulateCube(cases[index], c, corner, out);
        }
  }

private:
  EdgeKey keyOf(int edge, const glm::ivec3& c) const
  {
    const cube::Edge& e = cube::edges()[edge];
    const glm::ivec3 lower =
        c + glm::ivec3(cube::cornerOffset(e.lower, 0), cube::cornerOffset(e.lower, 1), cube::cornerOffset(e.lower, 2));
    return EdgeKey(e_.index(lower.x, lower.y, lower.z)) * 3 + e.axis;
  }

  // The cube-local position of the vertex on a cube edge.
  glm::dvec3 localPoint(int edge, const std::array<float, 8>& corner) const
  {
    const cube::Edge& e = cube::edges()[edge];
    glm::dvec3 p(cube::cornerOffset(e.lower, 0), cube::cornerOffset(e.lower, 1), cube::cornerOffset(e.lower, 2));
    p[e.axis] += edge_vertex::crossing(corner[e.lower], corner[e.upper], iso_);
    return p;
  }

  void triangulateCube(const cube::CubeCase& c, const glm::ivec3& cell, const std::array<float, 8>& corner,
                       BrickTriangles& out) const
  {
    triangulateCubeCase(
        c, [&](int edge) { return localPoint(edge, corner); },
        [&](int i, int j, int k) {
          out.triangles.push_back({keyOf(c.edges[i], cell), keyOf(c.edges[j], cell), keyOf(c.edges[k], cell)});
        });
  }

  const BandField& field_;
  Extent3 e_;
  float iso_;
};

}  // namespace

TriangleMesh extractSurface(const BandField& field, const GridFrame& frame, float isovalue)
{
  if (!(frame.extent == field.extent()))
    throw std::invalid_argument("the field is " + field.extent().toString() + " but its frame is " +
                                frame.extent.toString());
  if (!std::isfinite(isovalue)) throw UsageError("the iso value must be a finite number");
  for (float v : field.values())
    if (!std::isfinite(v)) throw NumericalError("the field holds a value that is not a finite number");

  const BrickSet& bricks = field.bricks();
  const size_t slots = bricks.activeCount();
  std::vector<BrickTriangles> perBrick(slots);
  const BrickCubes cubes(field, isovalue);
  std::vector<int8_t> sides(slots);
#pragma omp parallel for schedule(static)
  for (size_t s = 0; s < slots; ++s) sides[s] = cubes.sideOf(int32_t(s));
#pragma omp parallel for schedule(dynamic, 4)
  for (size_t s = 0; s < slots; ++s) cubes.triangulate(int32_t(s), sides, perBrick[s]);

  // Where each brick's triangles start in the mesh.
  std::vector<size_t> firstTriangle(slots + 1, 0);
  for (size_t s = 0; s < slots; ++s) firstTriangle[s + 1] = firstTriangle[s] + perBrick[s].triangles.size();
  const size_t triangleCount = firstTriangle[slots];

  // One vertex per cut edge: the edges' keys, sorted, number the vertices.
  // Each brick first sorts its own (most of its triangles' corners are
  // shared within it), so the sort over the whole surface and the look-ups
  // into it see each edge about once rather than six times. (All on the
  // threads: at --res 512 the sort and the look-ups took 320 of the 575 ms
  // when they ran on one.)
  std::vector<size_t> firstKey(slots + 1, 0);
#pragma omp parallel for schedule(dynamic, 16)
  for (size_t s = 0; s < slots; ++s) {
    std::vector<EdgeKey>& own = perBrick[s].keys;
    for (const auto& t : perBrick[s].triangles) own.insert(own.end(), t.begin(), t.end());
    std::sort(own.begin(), own.end());
    own.erase(std::unique(own.begin(), own.end()), own.end());
  }
  for (size_t s = 0; s < slots; ++s) firstKey[s + 1] = firstKey[s] + perBrick[s].keys.size();
  std::vector<EdgeKey> keys(firstKey[slots]);
#pragma omp parallel for schedule(dynamic, 16)
  for (size_t s = 0; s < slots; ++s)
    std::copy(perBrick[s].keys.begin(), perBrick[s].keys.end(), keys.begin() + ptrdiff_t(firstKey[s]));
  __gnu_parallel::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  if (keys.size() >= std::numeric_limits<uint32_t>::max())
    throw UsageError("the surface has more than 4 billion vertices; use a coarser grid");

  TriangleMesh mesh;
  mesh.triangles.resize(triangleCount);
#pragma omp parallel for schedule(dynamic, 16)
  for (size_t s = 0; s < slots; ++s) {
    const std::vector<EdgeKey>& own = perBrick[s].keys;
    std::vector<uint32_t> vertexOfOwn(own.size());
    for (size_t j = 0; j < own.size(); ++j)
      vertexOfOwn[j] = uint32_t(std::lower_bound(keys.begin(), keys.end(), own[j]) - keys.begin());
    auto vertexOf = [&](EdgeKey key) {
      return vertexOfOwn[size_t(std::lower_bound(own.begin(), own.end(), key) - own.begin())];
    };
    for (size_t k = 0; k < perBrick[s].triangles.size(); ++k) {
      const auto& t = perBrick[s].triangles[k];
      mesh.triangles[firstTriangle[s] + k] = glm::uvec3(vertexOf(t[0]), vertexOf(t[1]), vertexOf(t[2]));
    }
  }

  const Extent3 e = field.extent();
  const auto at = [&field](int x, int y, int z) { return field.at(x, y, z); };
  mesh.positions.resize(keys.size());
  mesh.normals.resize(keys.size());
#pragma omp parallel for schedule(static)
  for (size_t v = 0; v < keys.size(); ++v) {
    const int axis = int(keys[v] % 3);
    const uint64_t cell = keys[v] / 3;
    const glm::ivec3 a(int(cell % e.nx), int(cell / e.nx % e.ny), int(cell / e.nx / e.ny));
    glm::ivec3 b = a;
    ++b[axis];
    const float fa = field.at(a.x, a.y, a.z), fb = field.at(b.x, b.y, b.z);
    const double t = edge_vertex::crossing(fa, fb, isovalue);
    glm::dvec3 grid(a);
    grid[axis] += t;
    mesh.positions[v] = frame.toWorld(grid);
    mesh.normals[v] = edge_vertex::normal(edge_vertex::gradient(at, e, a.x, a.y, a.z),
                                          edge_vertex::gradient(at, e, b.x, b.y, b.z), t, axis, fa > isovalue);
  }
  return mesh;
}

}  // namespace lbmshape
