#include "lbmshape/mesh/mesh_validation.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <parallel/algorithm>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// Relative to the mesh's size: far thinner than any lattice can resolve, and
// well above the rounding of single-precision coordinates (about 6e-8), so a
// plane stored in float, tilted or not, is still recognised as flat.
constexpr double flatTolerance = 1e-6;

std::string coordinates(const glm::dvec3& p)
{
  std::ostringstream s;
  s << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  return s.str();
}

// A vertex far outside the rest of the mesh (a stray 1e30 in an export)
// would stretch the grid until the rest is a speck in one voxel, and the
// result would be empty or meaningless with nothing said. The rest's extent
// is measured without the outermost vertices (a five-hundredth at each end
// of each axis, at least four: a stray triangle's corners): when the whole
// mesh spans more than a thousand times that, the vertex farthest out is
// refused, by number.
void refuseStrayVertices(const TriangleMesh& mesh, const std::string& prefix)
{
  std::vector<uint8_t> used(mesh.positions.size(), 0);
  for (const auto& t : mesh.triangles) used[t[0]] = used[t[1]] = used[t[2]] = 1;
  std::vector<uint32_t> vertices;
  for (uint32_t v = 0; v < used.size(); ++v)
    if (used[v]) vertices.push_back(v);
  if (vertices.size() < 8) return;  // too few to tell a stray vertex from the shape
  const size_t outermost = std::max<size_t>(4, vertices.size() / 500);
  glm::dvec3 lo, hi;
  std::vector<double> values(vertices.size());
  for (int axis = 0; axis < 3; ++axis) {
    for (size_t k = 0; k < vertices.size(); ++k) values[k] = mesh.positions[vertices[k]][axis];
    std::nth_element(values.begin(), values.begin() + ptrdiff_t(outermost), values.end());
    lo[axis] = values[outermost];
    std::nth_element(values.begin(), values.end() - 1 - ptrdiff_t(outermost), values.end());
    hi[axis] = values[values.size() - 1 - outermost];
  }
  const double rest = glm::length(hi - lo);
  const Bounds whole = bounds(mesh);
  if (!(rest > 0.0) || whole.diagonal() <= 1000.0 * rest) return;
  const glm::dvec3 centre = 0.5 * (lo + hi);
  uint32_t farthest = vertices.front();
  for (uint32_t v : vertices)
    if (glm::length(mesh.positions[v] - centre) > glm::length(mesh.positions[farthest] - centre)) farthest = v;
  std::ostringstream s;
  s << prefix << "vertex " << farthest + 1 << " at " << coordinates(mesh.positions[farthest]) << " lies "
    << glm::length(mesh.positions[farthest] - centre) << " from the rest of the mesh, which spans " << rest
    << ": a grid around both would hold the rest in less than a voxel; remove the stray vertex";
  throw InputError(s.str());
}

// Triangles with the same corners, in the same turn, as an earlier one: a
// copy adds nothing to the surface, its distances or its sign (the winding
// number counts it twice inside and out), but a hierarchy cannot separate
// coincident triangles, so each search near them visits every copy: a
// cube's face repeated a million times (8 MB of OBJ) kept the distances
// busy for minutes. Compared by position, so copies in a triangle soup
// (STL) are found too; a face and its reverse are not copies.
size_t dropRepeatedTriangles(TriangleMesh& mesh)
{
  const auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  };
  // Corners from the one that sorts first, so the three turns of one
  // triangle compare alike and its mirror does not.
  const auto corners = [&](const glm::uvec3& t) {
    std::array<glm::dvec3, 3> c{mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    const int first = less(c[1], c[0]) ? (less(c[2], c[1]) ? 2 : 1) : (less(c[2], c[0]) ? 2 : 0);
    std::rotate(c.begin(), c.begin() + first, c.end());
    return c;
  };
  const auto hashOf = [](const std::array<glm::dvec3, 3>& c) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (const glm::dvec3& p : c)
      for (int k = 0; k < 3; ++k) h = (h ^ std::bit_cast<uint64_t>(p[k] + 0.0)) * 0x100000001b3ull;  // -0 as 0
    return uint32_t(h ^ (h >> 32));
  };
  // Each triangle as one number, its corners' hash above its index, sorted:
  // triangles of equal corners lie side by side (with the rare others whose
  // hash is the same), and in their file's order. Hashed and sorted on all
  // threads, in place of pairs sorted on one, which took as long again as
  // reading the file (25-30 ms for igea's 268,686 triangles).
  const size_t count = mesh.triangles.size();
  std::vector<uint64_t> keyed(count);
#pragma omp parallel for schedule(static)
  for (size_t t = 0; t < count; ++t) keyed[t] = uint64_t(hashOf(corners(mesh.triangles[t]))) << 32 | t;
  __gnu_parallel::sort(keyed.begin(), keyed.end());
  const auto hashPart = [](uint64_t key) { return key >> 32; };
  const auto triangleOf = [](uint64_t key) { return uint32_t(key); };
  std::vector<uint8_t> repeated;  // made only where a hash repeats
  for (size_t begin = 0; begin < count;) {
    size_t end = begin + 1;
    while (end < count && hashPart(keyed[end]) == hashPart(keyed[begin])) ++end;
    // A run of equal hashes sorted by its corners, then by file order:
    // each triangle with the corners of the one before is a copy, the first
    // of its corners kept (sorted, not compared pair by pair, so that many
    // distinct triangles of one hash cannot make it quadratic).
    if (end - begin > 1) {
      if (repeated.empty()) repeated.assign(count, 0);
      const auto cornersOf = [&](uint64_t key) { return corners(mesh.triangles[triangleOf(key)]); };
      std::sort(keyed.begin() + ptrdiff_t(begin), keyed.begin() + ptrdiff_t(end), [&](uint64_t a, uint64_t b) {
        const auto ca = cornersOf(a), cb = cornersOf(b);
        if (ca != cb) return std::lexicographical_compare(ca.begin(), ca.end(), cb.begin(), cb.end(), less);
        return triangleOf(a) < triangleOf(b);
      });
      for (size_t i = begin + 1; i < end; ++i)
        if (cornersOf(keyed[i]) == cornersOf(keyed[i - 1])) repeated[triangleOf(keyed[i])] = 1;
    }
    begin = end;
  }
  if (repeated.empty()) return 0;
  size_t kept = 0;
  for (size_t t = 0; t < count; ++t)
    if (!repeated[t]) mesh.triangles[kept++] = mesh.triangles[t];
  mesh.triangles.resize(kept);
  return count - kept;
}

}  // namespace

void requireWellFormed(const TriangleMesh& mesh, const std::string& name)
{
  const std::string prefix = "cannot read " + name + ": ";
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles[t][k] >= mesh.positions.size())
        throw InputError(prefix + "triangle " + std::to_string(t + 1) + " refers to vertex number " +
                         std::to_string(uint64_t(mesh.triangles[t][k]) + 1) + ", but there are only " +
                         std::to_string(mesh.positions.size()) + " vertices");
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    if (!isFinite(mesh.positions[v]))
      throw InputError(prefix + "vertex " + std::to_string(v + 1) + " has a coordinate that is not a finite number " +
                       coordinates(mesh.positions[v]));
    if (glm::any(glm::greaterThan(glm::abs(mesh.positions[v]), glm::dvec3(text::largestCoordinate))))
      throw InputError(prefix + "vertex " + std::to_string(v + 1) + " has a coordinate beyond single precision " +
                       coordinates(mesh.positions[v]));
  }
}

void validateInputMesh(TriangleMesh& mesh, const std::string& name, FlatMesh flat)
{
  const std::string prefix = "cannot read " + name + ": ";
  if (mesh.triangles.empty()) throw InputError(prefix + "it contains no triangles");
  requireWellFormed(mesh, name);

  const size_t before = mesh.triangles.size();
  std::erase_if(mesh.triangles, [&](const glm::uvec3& t) { return isDegenerate(mesh, t); });
  if (mesh.triangles.empty())
    throw InputError(prefix + "all " + std::to_string(before) + " triangles are degenerate (zero area)");
  if (mesh.triangles.size() < before)
    log::warning(name + ": dropped " + std::to_string(before - mesh.triangles.size()) +
                 " degenerate (zero-area) triangles of " + std::to_string(before));

  if (const size_t copies = dropRepeatedTriangles(mesh); copies > 0)
    log::warning(
        name + ": dropped " + std::to_string(copies) +
        (copies == 1 ? " triangle that repeats another's corners" : " triangles that repeat another's corners"));

  refuseStrayVertices(mesh, prefix);
  if (flat == FlatMesh::Allowed) return;

  if (mesh.triangles.size() == 1) throw InputError(prefix + "it is a single triangle, which encloses no volume");
  const Bounds box = bounds(mesh);
  const glm::dvec3 size = box.size();
  const double largest = std::max({size.x, size.y, size.z});
  const auto axisName = [](int axis) { return std::string(1, char('x' + axis)); };
  for (int axis = 0; axis < 3; ++axis) {
    if (size[axis] == 0)
      throw InputError(prefix + "it is flat (its bounding box has no extent along " + axisName(axis) +
                       "), so it encloses no volume");
    if (size[axis] <= flatTolerance * largest) {
      const int longest = int(std::max_element(&size.x, &size.x + 3) - &size.x);
      throw InputError(prefix + "its bounding box is " + threeSignificantDigits(largest) + " along " +
                       axisName(longest) + " but " + threeSignificantDigits(size[axis]) + " along " + axisName(axis) +
                       ": flat on any grid lbmshape can hold (are some of its parts far from the others?)");
    }
  }
  // Flat but tilted: every vertex in the plane of the largest triangle (the
  // one whose normal is known best).
  const glm::uvec3* largestTriangle = &mesh.triangles.front();
  double largestArea = 0;
  for (const auto& t : mesh.triangles)
    if (double area = glm::length(triangleAreaVector(mesh, t)); area > largestArea)
      largestArea = area, largestTriangle = &t;
  const glm::dvec3 normal = glm::normalize(triangleAreaVector(mesh, *largestTriangle));
  const glm::dvec3 origin = mesh.positions[(*largestTriangle)[0]];
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (std::abs(glm::dot(mesh.positions[t[k]] - origin, normal)) > flatTolerance * box.diagonal()) return;
  throw InputError(prefix + "it is flat (all its triangles lie in one plane), so it encloses no volume");
}

}  // namespace lbmshape
