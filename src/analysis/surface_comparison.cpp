// Samples are queried in parallel in fixed blocks. Inside a block each query
// passes the previous distance plus the step to the new point as an upper
// bound (distance to a surface changes no faster than the point moves), which
// prunes most of the tree; the bound changes the work, not the answer. Per-
// sample results are summed in sample order, so the thread count does not
// change a digit.
#include "lbmshape/analysis/surface_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "lbmshape/analysis/surface_sampling.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

namespace lbmshape {
namespace {

constexpr int64_t blockSize = 256;

bool hasArea(const TriangleMesh& mesh)
{
  for (const glm::dvec3& n : faceNormals(mesh))
    if (glm::dot(n, n) > 0.0) return true;
  return false;
}

struct Query {
  glm::dvec3 point;
  uint32_t triangle;  // the source face, or TriangleBvh::kNoTriangle for a vertex
};

DirectedDistance measure(const TriangleMesh& source, const TriangleMesh& target, const TriangleBvh& targetBvh,
                         const ComparisonOptions& options)
{
  const size_t random = randomSamplesOf(source, options);
  std::vector<Query> queries;
  queries.reserve(random + (options.includeVertices ? source.vertexCount() : 0));
  for (const SurfaceSample& s : sampleSurface(source, random, options.seed)) queries.push_back({s.point, s.triangle});
  if (options.includeVertices) {
    // Only the vertices that triangles use: a stray point is not surface.
    std::vector<bool> used(source.vertexCount(), false);
    for (const auto& t : source.triangles) used[t[0]] = used[t[1]] = used[t[2]] = true;
    for (size_t v = 0; v < source.vertexCount(); ++v)
      if (used[v]) queries.push_back({source.positions[v], TriangleBvh::kNoTriangle});
  }

  const std::vector<glm::dvec3> sourceNormals = faceNormals(source), targetNormals = faceNormals(target);
  std::vector<double> distance(queries.size()), angle(queries.size(), -1.0);
  const int64_t count = int64_t(queries.size());
  const interrupt::Watch stop;  // the threads below are not the call's
#pragma omp parallel for schedule(dynamic, 1)
  for (int64_t block = 0; block < (count + blockSize - 1) / blockSize; ++block) {
    if (options.stopsOnRequest && stop.requested()) continue;  // checked after the loop
    double previous = -1.0;
    glm::dvec3 previousPoint(0.0);
    for (int64_t i = block * blockSize; i < std::min(count, (block + 1) * blockSize); ++i) {
      const Query& q = queries[i];
      TriangleBvh::Closest c{0.0, q.point, TriangleBvh::kNoTriangle};
      if (previous >= 0.0) c = targetBvh.closest(q.point, previous + glm::length(q.point - previousPoint));
      if (c.triangle == TriangleBvh::kNoTriangle) c = targetBvh.closest(q.point);
      distance[i] = c.distance;
      previous = c.distance;
      previousPoint = q.point;
      if (q.triangle == TriangleBvh::kNoTriangle) continue;
      const glm::dvec3 n = sourceNormals[q.triangle], m = targetNormals[c.triangle];
      if (glm::dot(m, m) > 0.0 && glm::dot(n, n) > 0.0)
        angle[i] = glm::degrees(std::acos(std::clamp(glm::dot(n, m), -1.0, 1.0)));
    }
  }

  if (options.stopsOnRequest) interrupt::check("nothing was written");
  DirectedDistance result;
  result.samples = queries.size();
  double sum = 0.0, squares = 0.0, angles = 0.0;
  size_t angleCount = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    if (distance[i] > result.max) result.max = distance[i], result.farthest = queries[i].point;
    sum += distance[i];
    squares += distance[i] * distance[i];
    if (angle[i] >= 0.0) angles += angle[i], ++angleCount;
  }
  result.mean = sum / double(queries.size());
  result.rms = std::sqrt(squares / double(queries.size()));
  result.meanNormalAngle = angleCount ? angles / double(angleCount) : 0.0;
  return result;
}

}  // namespace

size_t randomSamplesOf(const TriangleMesh& mesh, const ComparisonOptions& options)
{
  return std::max(options.minSamples, size_t(std::ceil(options.samplesPerTriangle * double(mesh.triangleCount()))));
}

SurfaceComparison compareSurfaces(const TriangleMesh& a, const TriangleMesh& b, const ComparisonOptions& options)
{
  // The trees validate both meshes (indices, finite positions) before any sampling.
  const TriangleBvh treeA(a, TriangleBvh::Queries::ClosestOnly), treeB(b, TriangleBvh::Queries::ClosestOnly);
  return compareSurfaces(a, treeA, b, treeB, options);
}

SurfaceComparison compareSurfaces(const TriangleMesh& a, const TriangleBvh& treeA, const TriangleMesh& b,
                                  const TriangleBvh& treeB, const ComparisonOptions& options)
{
  if (!hasArea(a)) throw InputError("the first surface to compare has no triangle with area");
  if (!hasArea(b)) throw InputError("the second surface to compare has no triangle with area");
  SurfaceComparison result;
  result.aToB = measure(a, b, treeB, options);
  result.bToA = measure(b, a, treeA, options);
  result.hausdorff = std::max(result.aToB.max, result.bToA.max);
  result.mean = 0.5 * (result.aToB.mean + result.bToA.mean);
  result.rms = std::sqrt(0.5 * (result.aToB.rms * result.aToB.rms + result.bToA.rms * result.bToA.rms));
  result.meanNormalAngle = 0.5 * (result.aToB.meanNormalAngle + result.bToA.meanNormalAngle);
  return result;
}

DistanceToSurface::DistanceToSurface(const TriangleMesh& target)
    : target_(target), tree_(target, TriangleBvh::Queries::ClosestOnly)
{
  if (!hasArea(target)) throw InputError("the surface to measure against has no triangle with area");
}

DirectedDistance DistanceToSurface::from(const TriangleMesh& source, const ComparisonOptions& options) const
{
  if (!hasArea(source)) throw InputError("the surface to measure has no triangle with area");
  return measure(source, target_, tree_, options);
}

}  // namespace lbmshape
