#include "lbmshape/surface/triangle_relaxation.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "lbmshape/mesh/mesh_geometry.hpp"

namespace lbmshape {
namespace {

// triangleAreaVector() for positions that are not yet the mesh's.
glm::dvec3 crossOf(const std::vector<glm::dvec3>& p, const glm::uvec3& t)
{
  return glm::cross(p[t.y] - p[t.x], p[t.z] - p[t.x]);
}

// Whether each vertex is surrounded by its triangles: the edges opposite it
// (b -> c for the triangle a b c at a) then form one closed loop, so the
// numbers of their ends cancel, and their squares too (sums modulo 2^64:
// a boundary fan leaves first - last). A vertex on a hole, or on an edge
// of one triangle only, stays where it is.
std::vector<uint8_t> surroundedVertices(const TriangleMesh& mesh)
{
  std::vector<uint64_t> ends(mesh.vertexCount(), 0), squares(mesh.vertexCount(), 0);
  std::vector<uint8_t> used(mesh.vertexCount(), 0);
  auto opposite = [&](uint32_t v, uint64_t from, uint64_t to) {
    ends[v] += to - from;
    squares[v] += to * to - from * from;
    used[v] = 1;
  };
  for (const glm::uvec3& t : mesh.triangles) {
    opposite(t.x, t.y, t.z);
    opposite(t.y, t.z, t.x);
    opposite(t.z, t.x, t.y);
  }
  std::vector<uint8_t> surrounded(mesh.vertexCount());
  for (size_t v = 0; v < surrounded.size(); ++v) surrounded[v] = used[v] && ends[v] == 0 && squares[v] == 0;
  return surrounded;
}

// A triangle the move turned over or flattened (one that had no area to
// begin with has no side to turn).
bool turnedOver(const std::vector<glm::dvec3>& before, const std::vector<glm::dvec3>& after, const glm::uvec3& t)
{
  const glm::dvec3 was = crossOf(before, t);
  const double area2 = glm::dot(was, was);
  if (area2 == 0.0 || !std::isfinite(area2)) return false;
  return !(glm::dot(was, crossOf(after, t)) > 0.0);
}

}  // namespace

RelaxationSummary relaxTriangles(TriangleMesh& mesh, int rounds)
{
  if (rounds < 0) throw std::invalid_argument("relaxation rounds must not be negative");
  RelaxationSummary summary;
  if (rounds == 0 || mesh.triangles.empty()) return summary;
  for (const glm::dvec3& p : mesh.positions)
    if (!isFinite(p)) throw std::invalid_argument("relaxation needs finite vertex positions");
  const size_t n = mesh.vertexCount();
  const bool hasNormals = mesh.normals.size() == n;
  const std::vector<uint8_t> surrounded = surroundedVertices(mesh);

  std::vector<glm::dvec3> centres(n), normalSums(n), moved(n), movedNormals(n);
  std::vector<uint32_t> counts(n);
  for (int round = 0; round < rounds; ++round) {
    // The surface's normal at a vertex, whose plane the step keeps to: the
    // field's gradient where marching cubes gave it, else the triangles'.
    // (The triangles' plane where there is a gradient, a step off the
    // surface by the angle between the two, left vertices 0.03 voxel off a
    // sphere of radius 11.7 voxels.)
    const std::vector<glm::dvec3> facing = hasNormals ? std::vector<glm::dvec3>() : areaWeightedNormals(mesh);
    auto normalAt = [&](uint32_t v) { return hasNormals ? glm::dvec3(mesh.normals[v]) : facing[v]; };
    // The centre of a vertex's neighbours, and the mean of their normals:
    // each triangle adds its other two corners, so around a closed fan
    // every neighbour counts twice, alike.
    std::fill(centres.begin(), centres.end(), glm::dvec3(0.0));
    std::fill(normalSums.begin(), normalSums.end(), glm::dvec3(0.0));
    std::fill(counts.begin(), counts.end(), 0u);
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::dvec3 &a = mesh.positions[t.x], &b = mesh.positions[t.y], &c = mesh.positions[t.z];
      const glm::dvec3 na = normalAt(t.x), nb = normalAt(t.y), nc = normalAt(t.z);
      centres[t.x] += b + c, centres[t.y] += c + a, centres[t.z] += a + b;
      normalSums[t.x] += nb + nc, normalSums[t.y] += nc + na, normalSums[t.z] += na + nb;
      counts[t.x] += 2, counts[t.y] += 2, counts[t.z] += 2;
    }
#pragma omp parallel for schedule(static)
    for (size_t v = 0; v < n; ++v) {
      moved[v] = mesh.positions[v];
      movedNormals[v] = normalAt(uint32_t(v));
      const glm::dvec3 normal = movedNormals[v];
      if (!surrounded[v] || counts[v] == 0 || normal == glm::dvec3(0.0)) continue;
      const glm::dvec3 toCentre = centres[v] / double(counts[v]) - mesh.positions[v];
      const glm::dvec3 step = 0.5 * (toCentre - glm::dot(toCentre, normal) * normal);
      // Half the way to the neighbours, the normal is half the way to
      // theirs (the surface's normal changes smoothly along it). A step
      // along a surface that bends leaves it by half the bend times the
      // step squared, which the change of the normal along the step
      // measures: taken back along the normal, the vertex stays on the
      // surface to second order.
      const glm::dvec3 there = normal + 0.5 * (normalSums[v] / double(counts[v]) - normal);
      const double length = glm::length(there);
      if (!(length > 0.0)) continue;
      const double bend = glm::dot(there / length - normal, step);
      const glm::dvec3 to = mesh.positions[v] + (step - 0.5 * bend * normal);
      if (!isFinite(to)) continue;  // coordinates near the double's range
      moved[v] = to;
      movedNormals[v] = there / length;
    }
    // Moves that turn a triangle over are undone, its corners kept where
    // they were, until none does (at worst every vertex is kept: a
    // triangle is only found turned over while one of its corners moved).
    std::vector<uint8_t> isMoved(n), over(mesh.triangles.size());
    for (size_t v = 0; v < n; ++v) isMoved[v] = moved[v] != mesh.positions[v];
    summary.keptVertices = 0;
    for (bool undone = true; undone;) {
#pragma omp parallel for schedule(static)
      for (size_t k = 0; k < mesh.triangles.size(); ++k) {
        const glm::uvec3& t = mesh.triangles[k];
        over[k] = (isMoved[t.x] || isMoved[t.y] || isMoved[t.z]) && turnedOver(mesh.positions, moved, t);
      }
      undone = false;
      for (size_t k = 0; k < over.size(); ++k) {
        if (!over[k]) continue;
        for (const uint32_t v : {mesh.triangles[k].x, mesh.triangles[k].y, mesh.triangles[k].z})
          if (isMoved[v]) moved[v] = mesh.positions[v], isMoved[v] = 0, ++summary.keptVertices, undone = true;
      }
    }
    summary.movedVertices = 0;
    for (size_t v = 0; v < n; ++v) {
      if (!isMoved[v]) continue;
      ++summary.movedVertices;
      if (hasNormals) mesh.normals[v] = glm::vec3(movedNormals[v]);
    }
    mesh.positions.swap(moved);
  }
  return summary;
}

}  // namespace lbmshape
