// How far apart two surfaces are: distances from points spread over each
// surface to the other one, and how much their orientations disagree there.
// Used to measure a result against its reference (the input mesh, or an
// analytic shape), so neither mesh needs to be closed or manifold.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

namespace lbmshape {

struct ComparisonOptions {
  // Random points per surface: the larger of these two, plus every vertex
  // (which the extremes of a distance often sit on).
  size_t minSamples = 100000;
  double samplesPerTriangle = 10.0;
  bool includeVertices = true;
  uint64_t seed = 1;
  // A stop request ends the measuring with Interrupted (the compare
  // command, whose measuring is the whole job). Off where the comparison is
  // a frame's figures, whose call stops at its own next check.
  bool stopsOnRequest = false;
};

// What a comparison holds per sample while it measures one direction (the
// sample, its query, its distance and its angle), in bytes; and the random
// samples it takes of `mesh` (its vertices come on top). For refusing a
// comparison that cannot fit before it allocates.
inline constexpr double bytesPerComparisonSample = 96.0;
size_t randomSamplesOf(const TriangleMesh& mesh, const ComparisonOptions& options);

// From the samples of one surface (the source) to the other (the target).
// Distances are exact closest-point distances, in the meshes' units.
struct DirectedDistance {
  size_t samples = 0;
  double max = 0.0;          // one-sided Hausdorff distance
  glm::dvec3 farthest{0.0};  // the source sample at that distance
  double mean = 0.0;
  double rms = 0.0;
  // Mean over the random samples (not the vertices, which have no single
  // face) of the angle in degrees, 0 to 180, between the source's face normal
  // at the sample and the target's face normal at the closest point. Oriented:
  // a flipped triangle counts 180. Samples whose closest target triangle has
  // no area are left out.
  double meanNormalAngle = 0.0;
};

struct SurfaceComparison {
  DirectedDistance aToB, bToA;
  double hausdorff = 0.0;        // max(aToB.max, bToA.max)
  double mean = 0.0;             // (aToB.mean + bToA.mean) / 2
  double rms = 0.0;              // sqrt((aToB.rms^2 + bToA.rms^2) / 2)
  double meanNormalAngle = 0.0;  // (aToB.meanNormalAngle + bToA.meanNormalAngle) / 2
};

// Built on samples, so the maxima can only fall short of the true Hausdorff
// distance: by at most the spacing of the samples where it is attained. The
// result is the same for any number of threads, and both directions use the
// same seed, so swapping a and b swaps aToB and bToA exactly. Throws InputError when a
// mesh has no area, a bad index or a non-finite position.
SurfaceComparison compareSurfaces(const TriangleMesh& a, const TriangleMesh& b, const ComparisonOptions& options = {});
// The same with each mesh's tree already built (a morph's target's, built
// for its distances, is 40 ms of the armadillo): `treeA` must be a's tree,
// `treeB` b's.
SurfaceComparison compareSurfaces(const TriangleMesh& a, const TriangleBvh& treeA, const TriangleMesh& b,
                                  const TriangleBvh& treeB, const ComparisonOptions& options = {});

// Distances from many surfaces to one (a morph's frames to its target): the
// target's tree is built once. from(source) is compareSurfaces' aToB for
// (source, target). Keeps a reference to `target`.
class DistanceToSurface {
public:
  explicit DistanceToSurface(const TriangleMesh& target);
  DirectedDistance from(const TriangleMesh& source, const ComparisonOptions& options) const;

private:
  const TriangleMesh& target_;
  TriangleBvh tree_;
};

}  // namespace lbmshape
