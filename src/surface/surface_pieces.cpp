#include "lbmshape/surface/surface_pieces.hpp"

#include <algorithm>
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

// The cubes of one stored brick that extractSurface() triangulates: those
// whose lower corner lies in the brick and whose upper corner in the grid.
struct BrickCubeRange {
  glm::ivec3 origin, grid;

  bool holds(const glm::ivec3& local) const
  {
    return glm::all(glm::greaterThanEqual(local, glm::ivec3(0))) &&
           glm::all(glm::lessThan(local, glm::ivec3(brickEdge))) && glm::all(glm::lessThan(origin + local + 1, grid));
  }

  // Whether one of them has the edge from sample `lower` (brick-local)
  // along `axis`: the cubes with the same lower coordinate along the axis
  // and one less or the same along the other two.
  bool hasEdge(const glm::ivec3& lower, int axis) const
  {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for (int db = -1; db <= 0; ++db)
      for (int dc = -1; dc <= 0; ++dc) {
        glm::ivec3 cube = lower;
        cube[b] += db;
        cube[c] += dc;
        if (holds(cube)) return true;
      }
    return false;
  }
};

struct SlotPieces {
  std::vector<SurfaceCrossing> crossings;
  std::vector<SurfaceCube> cubes;
  double error = 0.0;
  bool finite = true;
};

void listSlot(const BandField& field, float iso, const BandField* base, float nearBand, int32_t slot, SlotPieces& out)
{
  const Extent3& e = field.extent();
  const float* values = field.values().data() + size_t(slot) * brickCells;
  for (int l = 0; l < brickCells; ++l)
    out.finite = out.finite && std::abs(values[l]) <= std::numeric_limits<float>::max();
  if (base) {
    const float* b = base->values().data() + size_t(slot) * brickCells;
    for (int l = 0; l < brickCells; ++l)
      if (std::abs(b[l]) <= nearBand) out.error = std::max(out.error, double(std::abs(values[l] - b[l])));
  }
  const BrickCubeRange range{brickEdge * field.bricks().brick(slot), glm::ivec3(e.nx, e.ny, e.nz)};
  const auto at = [&field](int x, int y, int z) { return field.at(x, y, z); };
  for (int z = 0; z <= brickEdge; ++z)
    for (int y = 0; y <= brickEdge; ++y)
      for (int x = 0; x <= brickEdge; ++x) {
        const glm::ivec3 local(x, y, z), g = range.origin + local;
        if (glm::any(glm::greaterThanEqual(g, range.grid))) continue;
        const float here = field.at(g.x, g.y, g.z);
        for (int axis = 0; axis < 3; ++axis) {
          if (local[axis] == brickEdge || !range.hasEdge(local, axis)) continue;
          glm::ivec3 u = g;
          ++u[axis];
          const float there = field.at(u.x, u.y, u.z);
          if ((here > iso) == (there > iso)) continue;
          const double t = edge_vertex::crossing(here, there, iso);
          const glm::vec3 normal =
              edge_vertex::normal(edge_vertex::gradient(at, e, g.x, g.y, g.z),
                                  edge_vertex::gradient(at, e, u.x, u.y, u.z), t, axis, here > iso);
          out.crossings.push_back({uint64_t(e.index(g.x, g.y, g.z)) * 3 + uint64_t(axis), here, there, normal});
        }
        if (!range.holds(local)) continue;
        int cubeCase = 0;
        for (int c = 0; c < 8; ++c)
          if (field.at(g.x + (c & 1), g.y + (c >> 1 & 1), g.z + (c >> 2 & 1)) > iso) cubeCase |= 1 << c;
        if (cubeCase != 0 && cubeCase != 255)
          out.cubes.push_back({uint64_t(e.index(g.x, g.y, g.z)), uint32_t(cubeCase),
                               uint32_t(slot) * brickCells + uint32_t(cellInBrick(x, y, z))});
      }
}

glm::ivec3 cellOf(uint64_t index, const Extent3& e)
{
  const auto [x, y, z] = e.cellAt(size_t(index));
  return glm::ivec3(x, y, z);
}

}  // namespace

void SurfacePieces::tidy()
{
  __gnu_parallel::sort(crossings.begin(), crossings.end());
  crossings.erase(std::unique(crossings.begin(), crossings.end(),
                              [](const SurfaceCrossing& a, const SurfaceCrossing& b) { return a.key == b.key; }),
                  crossings.end());
  __gnu_parallel::sort(cubes.begin(), cubes.end());
}

SurfacePieces listSurfacePieces(const BandField& field, const SurfaceRequest& request, const BandField* base)
{
  const float isovalue = request.isovalue, nearBand = request.nearBand;
  if (nearBand < 0.0f) base = nullptr;
  if (base && base->sharedBricks() != field.sharedBricks() &&
      !(base->bricks().cells() == field.bricks().cells() && base->values().size() == field.values().size()))
    throw std::invalid_argument("the base lies on other bricks than the field");
  const size_t slots = field.bricks().activeCount();
  std::vector<SlotPieces> perSlot(slots);
#pragma omp parallel for schedule(dynamic, 16)
  for (size_t s = 0; s < slots; ++s) listSlot(field, isovalue, base, nearBand, int32_t(s), perSlot[s]);

  SurfacePieces pieces;
  pieces.extent = field.extent();
  pieces.isovalue = isovalue;
  double error = 0.0;
  for (const SlotPieces& slot : perSlot) {
    if (!slot.finite) throw NumericalError("the field holds a value that is not a finite number");
    pieces.crossings.insert(pieces.crossings.end(), slot.crossings.begin(), slot.crossings.end());
    pieces.cubes.insert(pieces.cubes.end(), slot.cubes.begin(), slot.cubes.end());
    error = std::max(error, slot.error);
  }
  if (base) pieces.errorNearBase = error;
  for (const glm::ivec3& c : request.probes) {
    if (!field.extent().contains(c.x, c.y, c.z)) throw std::invalid_argument("a probe beyond the grid");
    pieces.probeValues.push_back(field.at(c.x, c.y, c.z));
  }
  pieces.tidy();
  return pieces;
}

TriangleMesh assembleSurface(const SurfacePieces& pieces, const GridFrame& frame)
{
  if (!(frame.extent == pieces.extent))
    throw std::invalid_argument("the pieces are of a " + pieces.extent.toString() + " grid but the frame is " +
                                frame.extent.toString());
  const Extent3& e = pieces.extent;
  const std::vector<SurfaceCrossing>& crossings = pieces.crossings;
  if (crossings.size() >= std::numeric_limits<uint32_t>::max())
    throw UsageError("the surface has more than 4 billion vertices; use a coarser grid");

  TriangleMesh mesh;
  mesh.positions.resize(crossings.size());
  mesh.normals.resize(crossings.size());
#pragma omp parallel for schedule(static)
  for (size_t v = 0; v < crossings.size(); ++v) {
    const SurfaceCrossing& c = crossings[v];
    glm::dvec3 grid(cellOf(c.key / 3, e));
    grid[int(c.key % 3)] += edge_vertex::crossing(c.lower, c.upper, pieces.isovalue);
    mesh.positions[v] = frame.toWorld(grid);
    mesh.normals[v] = c.normal;
  }

  const auto& cases = cube::cubeCases();
  std::vector<size_t> firstTriangle(pieces.cubes.size() + 1, 0);
  for (size_t k = 0; k < pieces.cubes.size(); ++k)
    firstTriangle[k + 1] = firstTriangle[k] + size_t(cases[pieces.cubes[k].cubeCase].triangleCount());
  mesh.triangles.resize(firstTriangle.back());
  bool complete = true;
#pragma omp parallel for schedule(static) reduction(&& : complete)
  for (size_t k = 0; k < pieces.cubes.size(); ++k) {
    const SurfaceCube& cube = pieces.cubes[k];
    const cube::CubeCase& c = cases[cube.cubeCase];
    const glm::ivec3 corner = cellOf(cube.index, e);
    // The vertex of each of the case's cut edges, and where it lies in the cube.
    std::array<uint32_t, 12> vertex{};
    std::array<glm::dvec3, 12> local;
    for (int i = 0; i < c.edgeCount; ++i) {
      const cube::Edge& edge = cube::edges()[c.edges[size_t(i)]];
      const glm::ivec3 offset(cube::cornerOffset(edge.lower, 0), cube::cornerOffset(edge.lower, 1),
                              cube::cornerOffset(edge.lower, 2));
      const glm::ivec3 lower = corner + offset;
      const uint64_t key = uint64_t(e.index(lower.x, lower.y, lower.z)) * 3 + edge.axis;
      const auto found = std::lower_bound(crossings.begin(), crossings.end(), SurfaceCrossing{key});
      if (found == crossings.end() || found->key != key) {
        complete = false;
        break;
      }
      vertex[size_t(i)] = uint32_t(found - crossings.begin());
      local[size_t(i)] = glm::dvec3(offset);
      local[size_t(i)][edge.axis] += edge_vertex::crossing(found->lower, found->upper, pieces.isovalue);
    }
    if (!complete) continue;
    size_t next = firstTriangle[k];
    triangulateCubeCase(
        c,
        [&](int edge) {
          for (int i = 0; i < c.edgeCount; ++i)
            if (c.edges[size_t(i)] == edge) return local[size_t(i)];
          return glm::dvec3(0.0);
        },
        [&](int i, int j, int l) {
          mesh.triangles[next++] = glm::uvec3(vertex[size_t(i)], vertex[size_t(j)], vertex[size_t(l)]);
        });
  }
  if (!complete) throw NumericalError("a cut cube's edge is missing from the surface's crossings");
  return mesh;
}

}  // namespace lbmshape
