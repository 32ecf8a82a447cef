#include "lbmshape/surface/band_marching_cubes.hpp"

#include <algorithm>
#include <exception>
#include <array>
#include <bitset>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <parallel/algorithm>

#include "lbmshape/core/error.hpp"
#include "lbmshape/surface/case_triangulation.hpp"
#include "lbmshape/surface/cube_cases.hpp"
#include "lbmshape/surface/edge_vertex.hpp"

namespace lbmshape {
namespace {

// A cut grid edge, named by the grid index of its lower sample and its axis.
using EdgeKey = uint64_t;

// The same edge named within the brick whose cubes cut it: its lower sample
// (0..8 along each axis, 8 being the next brick's first layer) and its axis.
// Within one brick these ids are in the order of the edges' keys (z, then y,
// then x, then the axis), so a brick's edges listed by id are sorted by key.
using LocalEdge = uint16_t;
constexpr int sampleSide = brickEdge + 1;
constexpr int localEdgeCount = 3 * sampleSide * sampleSide * sampleSide;
constexpr int sampleIndex(int x, int y, int z) { return x + sampleSide * (y + sampleSide * z); }

struct BrickTriangles {
  std::vector<std::array<LocalEdge, 3>> triangles;
  std::vector<LocalEdge> edges;  // those its triangles use, each once, in order
  std::vector<EdgeKey> keys;     // of the same edges
};

// Whether each of a brick's 9^3 samples is above the isovalue, four at a
// time: bit 0 at (x, y, z), 1 at (x, y + 1, z), 2 at (x, y, z + 1), 3 at
// (x, y + 1, z + 1). A cube's case is its two columns' codes interleaved.
constexpr std::array<uint8_t, 16> spreadColumn = [] {
  std::array<uint8_t, 16> spread{};
  for (int c = 0; c < 16; ++c)
    for (int bit = 0; bit < 4; ++bit) spread[size_t(c)] |= uint8_t((c >> bit & 1) << (2 * bit));
  return spread;
}();

class BrickCubes {
public:
  BrickCubes(const BandField& field, float iso) : field_(field), e_(field.extent()), iso_(iso) {}

  // +1 when every stored cell of the slot is above the isovalue, -1 when
  // every one is at or below it, 0 when mixed; `finite` false when one is
  // NaN or infinite. (Counts, not branches: the loop vectorizes.)
  int8_t sideOf(int32_t slot, bool& finite) const
  {
    const float* v = field_.values().data() + size_t(slot) * brickCells;
    int above = 0, notFinite = 0;
    for (int l = 0; l < brickCells; ++l) {
      above += int(v[l] > iso_);
      notFinite |= int(!(std::abs(v[l]) <= std::numeric_limits<float>::max()));
    }
    finite = notFinite == 0;
    return above == brickCells ? 1 : above == 0 ? -1 : 0;
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
    std::array<float, sampleSide * sampleSide * sampleSide> sample;
    for (int z = 0; z < sampleSide; ++z)
      for (int y = 0; y < sampleSide; ++y)
        for (int x = 0; x < sampleSide; ++x) {
          const int k = (x >> 3) | (y >> 3) << 1 | (z >> 3) << 2;
          sample[size_t(sampleIndex(x, y, z))] =
              from[size_t(k)] ? from[size_t(k)][cellInBrick(x & 7, y & 7, z & 7)] : far[size_t(k)];
        }
    std::array<uint8_t, sample.size()> above;
    for (size_t i = 0; i < sample.size(); ++i) above[i] = uint8_t(sample[i] > iso_);

    const glm::ivec3 origin = brickEdge * b;
    // The cubes that lie inside the grid: those whose upper corner does.
    const glm::ivec3 end = glm::min(glm::ivec3(brickEdge), glm::ivec3(e_.nx, e_.ny, e_.nz) - 1 - origin);
    const auto& cases = cube::cubeCases();
    std::array<uint8_t, sampleSide> column;
    for (int lz = 0; lz < end.z; ++lz)
      for (int ly = 0; ly < end.y; ++ly) {
        for (int x = 0; x <= end.x; ++x)
          column[size_t(x)] = uint8_t(
              above[size_t(sampleIndex(x, ly, lz))] | above[size_t(sampleIndex(x, ly + 1, lz))] << 1 |
              above[size_t(sampleIndex(x, ly, lz + 1))] << 2 | above[size_t(sampleIndex(x, ly + 1, lz + 1))] << 3);
        for (int lx = 0; lx < end.x; ++lx) {
          const int index = spreadColumn[column[size_t(lx)]] | spreadColumn[column[size_t(lx + 1)]] << 1;
          if (index == 0 || index == 255) continue;
          std::array<float, 8> corner;
          for (int k = 0; k < 8; ++k)
            corner[size_t(k)] = sample[size_t(sampleIndex(lx + (k & 1), ly + (k >> 1 & 1), lz + (k >> 2 & 1)))];
          triangulateCube(cases[size_t(index)], glm::ivec3(lx, ly, lz), corner, out);
        }
      }
    listEdges(origin, out);
  }

private:
  static LocalEdge localEdgeOf(int edge, const glm::ivec3& cube)
  {
    const cube::Edge& e = cube::edges()[size_t(edge)];
    const glm::ivec3 lower = cube + glm::ivec3(cube::cornerOffset(e.lower, 0), cube::cornerOffset(e.lower, 1),
                                               cube::cornerOffset(e.lower, 2));
    return LocalEdge(e.axis + 3 * sampleIndex(lower.x, lower.y, lower.z));
  }

  // The cube-local position of the vertex on a cube edge.
  glm::dvec3 localPoint(int edge, const std::array<float, 8>& corner) const
  {
    const cube::Edge& e = cube::edges()[size_t(edge)];
    glm::dvec3 p(cube::cornerOffset(e.lower, 0), cube::cornerOffset(e.lower, 1), cube::cornerOffset(e.lower, 2));
    p[e.axis] += edge_vertex::crossing(corner[e.lower], corner[e.upper], iso_);
    return p;
  }

  void triangulateCube(const cube::CubeCase& c, const glm::ivec3& cube, const std::array<float, 8>& corner,
                       BrickTriangles& out) const
  {
    triangulateCubeCase(
        c, [&](int edge) { return localPoint(edge, corner); },
        [&](int i, int j, int k) {
          out.triangles.push_back(
              {localEdgeOf(c.edges[i], cube), localEdgeOf(c.edges[j], cube), localEdgeOf(c.edges[k], cube)});
        });
  }

  // The edges the brick's triangles use, in order, and their keys.
  void listEdges(const glm::ivec3& origin, BrickTriangles& out) const
  {
    std::bitset<localEdgeCount> used;
    for (const auto& t : out.triangles)
      for (LocalEdge edge : t) used.set(edge);
    out.edges.reserve(used.count());
    for (int edge = int(used._Find_first()); edge < localEdgeCount; edge = int(used._Find_next(size_t(edge))))
      out.edges.push_back(LocalEdge(edge));
    out.keys.reserve(out.edges.size());
    for (LocalEdge edge : out.edges) {
      const int sample = edge / 3;
      const glm::ivec3 lower = origin + glm::ivec3(sample % sampleSide, sample / sampleSide % sampleSide,
                                                   sample / (sampleSide * sampleSide));
      out.keys.push_back(EdgeKey(e_.index(lower.x, lower.y, lower.z)) * 3 + EdgeKey(edge % 3));
    }
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

  const BrickSet& bricks = field.bricks();
  const size_t slots = bricks.activeCount();
  std::vector<BrickTriangles> perBrick(slots);
  const BrickCubes cubes(field, isovalue);
  std::vector<int8_t> sides(slots);
  bool allFinite = true;
#pragma omp parallel for schedule(static) reduction(&& : allFinite)
  for (size_t s = 0; s < slots; ++s) {
    bool finite = true;
    sides[s] = cubes.sideOf(int32_t(s), finite);
    allFinite = allFinite && finite;
  }
  if (!allFinite) throw NumericalError("the field holds a value that is not a finite number");
  // The triangles' lists grow as they are made: an allocation that fails
  // (under an address-space limit) must not leave the parallel loop, which
  // ends the process at once, beside the device's threads (a morph under
  // `ulimit -v 800000` died of SIGSEGV one run in twenty): the first
  // failure is kept and thrown after the loop.
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 4)
  for (size_t s = 0; s < slots; ++s) {
    try {
      cubes.triangulate(int32_t(s), sides, perBrick[s]);
    } catch (...) {
#pragma omp critical(lbmshape_band_marching_cubes_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);

  // Where each brick's triangles start in the mesh.
  std::vector<size_t> firstTriangle(slots + 1, 0);
  for (size_t s = 0; s < slots; ++s) firstTriangle[s + 1] = firstTriangle[s] + perBrick[s].triangles.size();
  const size_t triangleCount = firstTriangle[slots];

  // One vertex per cut edge: the edges' keys, sorted, number the vertices.
  // Each brick lists its own edges in key order (BrickCubes::listEdges), so
  // the sort over the whole surface sees each edge about once rather than
  // six times, and a triangle finds its corners' vertices by their ids in
  // the brick, not by searching.
  std::vector<size_t> firstKey(slots + 1, 0);
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
#pragma omp parallel
  {
    std::array<uint32_t, localEdgeCount> vertexOfEdge;  // read only where the brick's edges set it
#pragma omp for schedule(dynamic, 16)
    for (size_t s = 0; s < slots; ++s) {
      const BrickTriangles& brick = perBrick[s];
      auto from = keys.begin();
      for (size_t j = 0; j < brick.edges.size(); ++j) {
        from = std::lower_bound(from, keys.end(), brick.keys[j]);  // the brick's keys ascend
        vertexOfEdge[brick.edges[j]] = uint32_t(from - keys.begin());
      }
      for (size_t k = 0; k < brick.triangles.size(); ++k) {
        const auto& t = brick.triangles[k];
        mesh.triangles[firstTriangle[s] + k] = glm::uvec3(vertexOfEdge[t[0]], vertexOfEdge[t[1]], vertexOfEdge[t[2]]);
      }
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
    const auto [x, y, z] = e.cellAt(cell);
    const glm::ivec3 a(x, y, z);
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
