#include "lbmshape/sdf/signed_distance.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/sdf/band_distance.hpp"
#include "lbmshape/sdf/far_field.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
#include "lbmshape/sdf/winding_gradient_bound.hpp"
#include "lbmshape/sdf/winding_sign.hpp"

namespace lbmshape {

void checkSignedDistanceArguments(const TriangleMesh& mesh, const GridFrame& frame, double bandVoxels)
{
  if (mesh.triangles.empty()) throw InputError("the mesh has no triangles: there is no surface to measure from");
  if (frame.extent.nx <= 0 || frame.extent.ny <= 0 || frame.extent.nz <= 0)
    throw UsageError("the grid has no cells (extent " + frame.extent.toString() + ")");
  // Cells are numbered in 32 bits inside the distance stages.
  if (frame.extent.cells() >= std::numeric_limits<uint32_t>::max())
    throw UsageError("the grid " + frame.extent.toString() + " has too many cells (at most 4e9); use a coarser grid");
  if (!(frame.voxel > 0.0) || !std::isfinite(frame.voxel)) throw UsageError("the grid's voxel size must be positive");
  // Below one voxel the sign stage could not tell, from the band alone,
  // which neighbouring cells have no surface between them.
  if (!(bandVoxels >= 1.0) || !std::isfinite(bandVoxels)) {
    std::ostringstream m;
    m << "the exact band must be at least 1 voxel wide (got " << bandVoxels << ")";
    throw UsageError(m.str());
  }
}

Volume signedDistance(const TriangleMesh& mesh, const GridFrame& frame, const SignedDistanceOptions& options,
                      SignedDistanceStats* stats)
{
  checkSignedDistanceArguments(mesh, frame, options.bandVoxels);
  SignedDistanceStats local;
  SignedDistanceStats& s = stats ? *stats : local;
  s = SignedDistanceStats{};
  s.cells = frame.extent.cells();
  s.triangles = mesh.triangles.size();
  const Stopwatch total;

  // Each part's share of the time, as measured on the armadillo at 128^3.
  const auto beginPart = [&](const char* part, double weight) {
    if (options.progress) options.progress->beginPart(part, 1.0, weight);
  };
  Stopwatch stage;
  beginPart("hierarchy", 0.08);
  const TriangleBvh bvh(mesh);
  s.bvhMs = stage.ms();

  stage.restart();
  Volume distance(frame.extent, std::numeric_limits<float>::infinity());
  std::vector<uint32_t> nearest(s.cells, TriangleBvh::kNoTriangle);
  s.bandCells = exactBandDistances(bvh, frame, options.bandVoxels, distance, nearest, options.progress, 0.37);
  s.bandMs = stage.ms();
  interrupt::check("nothing was written");

  // The sign needs only to know which cells are more than a voxel from the
  // surface, which the band already tells (the rest are still infinite).
  stage.restart();
  beginPart("winding-number sign", 0.15);
  const WindingGradientBound gradient(mesh);
  s.openEdges = gradient.openEdgeCount();
  const std::vector<uint8_t> inside = insideByWindingNumber(bvh, gradient, frame, distance, s.windingEvaluations);
  s.signMs = stage.ms();

  stage.restart();
  beginPart("far field", 0.40);
  // The far field spreads only the triangles that cells hold. Every part of
  // the surface inside the grid has a band cell within a voxel; when some of
  // the mesh lies beyond the grid, the cells on its faces bring that in.
  const Bounds box = bounds(mesh);
  const glm::dvec3 last = frame.cellCentre(frame.extent.nx - 1, frame.extent.ny - 1, frame.extent.nz - 1);
  const bool contained =
      glm::all(glm::greaterThanEqual(box.min, frame.origin)) && glm::all(glm::lessThanEqual(box.max, last));
  if (!contained || s.bandCells == 0) s.farCells = exactFaceDistances(bvh, frame, distance, nearest);
  s.farCells += propagateFarField(bvh, frame, distance, nearest, options.exactEverywhere);
  float* values = distance.data();
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < s.cells; ++i)
    if (!inside[i]) values[i] = -values[i];
  s.farFieldMs = stage.ms();

  s.totalMs = total.ms();
  return distance;
}

}  // namespace lbmshape
