// signedDistance against independent oracles: analytic shapes, brute-force
// distances and brute-force winding numbers, on closed, open, overlapping
// and self-intersecting inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <omp.h>
#include <random>

#include "lbmshape/core/error.hpp"
#include "lbmshape/sdf/signed_distance.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
#include "support/test_meshes.hpp"

#include "sdf_fixtures.hpp"

namespace lbmshape {
namespace {

constexpr double kBand = 3.0;    // voxels within which distances must be exact
constexpr double kExact = 1e-3;  // voxels

glm::dvec3 centreOf(const GridFrame& frame, size_t i)
{
  const Extent3& e = frame.extent;
  return frame.cellCentre(int(i % e.nx), int(i / e.nx % e.ny), int(i / e.nx / e.ny));
}

// Analytic signed distance of an axis-aligned box, positive inside.
double boxDistance(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi)
{
  const glm::dvec3 q = glm::abs(p - 0.5 * (lo + hi)) - 0.5 * (hi - lo);
  const double outside = glm::length(glm::max(q, glm::dvec3(0.0)));
  const double inside = std::min(std::max({q.x, q.y, q.z}), 0.0);
  return -(outside + inside);
}

// Every cell within the band must carry the brute-force distance. Which
// cells those are is decided by the brute force too, over every cell, so
// the code under test cannot leave a cell out of the check.
void expectExactBand(const TriangleMesh& mesh, const GridFrame& frame, const Volume& sdf, size_t* checked = nullptr)
{
  size_t count = 0;
  double worst = 0.0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : count) reduction(max : worst)
  for (size_t i = 0; i < sdf.size(); ++i) {
    const double truth = testing::sdf::bruteForceDistance(mesh, centreOf(frame, i)) / frame.voxel;
    if (truth > kBand) continue;
    worst = std::max(worst, std::abs(std::abs(double(sdf[i])) - truth));
    ++count;
  }
  EXPECT_LT(worst, kExact) << "over " << count << " band cells";
  EXPECT_GT(count, 0u);
  if (checked) *checked = count;
}

TEST(SignedDistance, SphereBandIsTheExactDistanceToThePolygon)
{
  const glm::dvec3 centre(0.03, -0.02, 0.01);
  const double radius = 1.0;
  const TriangleMesh sphere = testing::icosphere(3, radius, centre);
  const GridFrame frame = frameWithResolution(bounds(sphere), 36, 3);
  SignedDistanceStats stats;
  const Volume sdf = signedDistance(sphere, frame, {}, &stats);
  size_t band = 0;
  expectExactBand(sphere, frame, sdf, &band);
  EXPECT_EQ(stats.bandCells, band);

  // Against the round sphere the polygon may differ by its sagitta, the gap
  // between the sphere and the innermost face plane, and by no more.
  const double sagitta = (radius - testing::sdf::innerRadius(sphere, centre)) / frame.voxel;
  ASSERT_GT(sagitta, 0.05);  // the comparison below is not vacuous
  double worst = 0.0;
  for (size_t i = 0; i < sdf.size(); ++i) {
    const double analytic = (radius - glm::length(centreOf(frame, i) - centre)) / frame.voxel;
    if (std::abs(sdf[i]) > kBand) continue;
    worst = std::max(worst, std::abs(sdf[i] - analytic));
    ASSERT_LE(std::abs(sdf[i] - analytic), sagitta + kExact) << "cell " << i;
  }
  std::cout << "sphere: sagitta " << sagitta << " voxel, largest departure from the round sphere " << worst << "\n";
}

TEST(SignedDistance, BoxMatchesTheAnalyticDistanceEverywhere)
{
  const glm::dvec3 lo(-0.9, -0.5, -0.7), hi(0.8, 0.6, 0.5);
  const TriangleMesh mesh = testing::box(lo, hi);
  const GridFrame frame = frameWithResolution(bounds(mesh), 48, 6);
  const Volume sdf = signedDistance(mesh, frame);
  double band = 0.0, far = 0.0;
  for (size_t i = 0; i < sdf.size(); ++i) {
    const double analytic = boxDistance(centreOf(frame, i), lo, hi) / frame.voxel;
    const double error = std::abs(sdf[i] - analytic);
    if (std::abs(analytic) <= kBand)
      band = std::max(band, error);
    else
      far = std::max(far, error);
  }
  std::cout << "box: worst error " << band << " voxel in the band, " << far << " voxel beyond\n";
  EXPECT_LT(band, kExact);
  EXPECT_LT(far, 0.1);
}

TEST(SignedDistance, BandIsExactOnASelfIntersectingSoup)
{
  // A bumpy sphere through a box: overlapping, non-manifold where they cross.
  TriangleMesh bumpy = testing::icosphere(3, 0.8);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.9, 1.1);
  for (auto& p : bumpy.positions) p *= u(rng);
  const TriangleMesh mesh = testing::merged(bumpy, testing::box({0.2, -0.3, -0.4}, {1.1, 0.5, 0.3}));
  const GridFrame frame = frameWithResolution(bounds(mesh), 40, 3);
  expectExactBand(mesh, frame, signedDistance(mesh, frame));
}

// The sign against the brute-force winding number at every cell whose
// winding number is not within 1e-3 of one half.
void expectSignMatchesWindingNumber(const TriangleMesh& mesh, int resolution)
{
  const GridFrame frame = frameWithResolution(bounds(mesh), resolution, 3);
  SignedDistanceStats stats;
  const Volume sdf = signedDistance(mesh, frame, {}, &stats);
  const TriangleBvh bvh(mesh);
  size_t compared = 0, inside = 0;
  for (size_t i = 0; i < sdf.size(); ++i) {
    const double w = bvh.exactWindingNumber(centreOf(frame, i));
    if (std::abs(w - 0.5) < 1e-3) continue;
    ++compared;
    inside += w > 0.5;
    ASSERT_EQ(sdf[i] > 0.0f, w > 0.5) << "cell " << i << " with winding number " << w << " and distance " << sdf[i];
  }
  EXPECT_GT(inside, 0u);
  EXPECT_GT(compared, sdf.size() * 9 / 10);
  std::cout << mesh.triangles.size() << " triangles, " << stats.openEdges << " open edges: sign right at all "
            << compared << " cells, with " << stats.windingEvaluations << " winding-number evaluations\n";
}

TEST(SignedDistance, SignIsTheBruteForceWindingNumberSign)
{
  const TriangleMesh sphere = testing::icosphere(3, 1.0);
  const TriangleMesh second = testing::icosphere(2, 0.6, {0.9, 0.3, -0.2});
  expectSignMatchesWindingNumber(sphere, 28);
  // Closed, with regions of winding number 0, 1 and 2: a sphere inside a
  // sphere, each region signed by one evaluation.
  expectSignMatchesWindingNumber(testing::merged(sphere, testing::icosphere(2, 0.5, {0.1, 0.0, 0.1})), 28);
  expectSignMatchesWindingNumber(testing::sdf::withHoles(sphere, 40, 2), 28);
  expectSignMatchesWindingNumber(testing::merged(testing::sdf::withHoles(sphere, 8, 3), second), 28);
  // Inconsistent orientation: a band of flipped triangles makes w swing
  // around one half all over; the sign must still follow it.
  TriangleMesh flipped = sphere;
  for (size_t t = 0; t < flipped.triangles.size(); t += 3) std::swap(flipped.triangles[t].y, flipped.triangles[t].z);
  expectSignMatchesWindingNumber(flipped, 20);
}

TEST(SignedDistance, TwoOverlappingSpheresAreOneSolid)
{
  const glm::dvec3 ca(-0.3, 0.0, 0.0), cb(0.4, 0.1, 0.0);
  const TriangleMesh a = testing::icosphere(3, 0.6, ca), b = testing::icosphere(3, 0.5, cb);
  const TriangleMesh mesh = testing::merged(a, b);
  const GridFrame frame = frameWithResolution(bounds(mesh), 40, 3);
  const Volume sdf = signedDistance(mesh, frame);
  // Margins: the polygons sit up to their sagitta inside the round spheres.
  const double sagitta = std::max(0.6 - testing::sdf::innerRadius(a, ca), 0.5 - testing::sdf::innerRadius(b, cb));
  size_t overlap = 0;
  for (size_t i = 0; i < sdf.size(); ++i) {
    const glm::dvec3 p = centreOf(frame, i);
    const double da = 0.6 - glm::length(p - ca), db = 0.5 - glm::length(p - cb);  // positive inside each
    if (da > sagitta + 1e-9 || db > sagitta + 1e-9) {
      ASSERT_GT(sdf[i], 0.0f) << "cell " << i;
    } else if (da < -1e-9 && db < -1e-9) {
      ASSERT_LT(sdf[i], 0.0f) << "cell " << i;
    }
    // In the overlap the distance is still to the nearest triangle, the
    // buried wall of the other sphere included.
    if (da > sagitta && db > sagitta) {
      ++overlap;
      EXPECT_NEAR(sdf[i], std::min(da, db) / frame.voxel, sagitta / frame.voxel + kExact);
    }
  }
  EXPECT_GT(overlap, 100u);
}

// Inside/outside of `holey` against `closed` at the cells more than two
// voxels from the closed surface: the fraction that agree.
double agreement(const TriangleMesh& closed, const TriangleMesh& holey, int resolution)
{
  const GridFrame frame = frameWithResolution(bounds(closed), resolution, 3);
  const Volume reference = signedDistance(closed, frame);
  SignedDistanceStats stats;
  const Volume open = signedDistance(holey, frame, {}, &stats);
  size_t counted = 0, same = 0;
  for (size_t i = 0; i < reference.size(); ++i) {
    if (std::abs(reference[i]) <= 2.0f) continue;
    ++counted;
    same += (reference[i] > 0) == (open[i] > 0);
  }
  std::cout << holey.triangles.size() << " of " << closed.triangles.size() << " triangles (" << stats.openEdges
            << " open edges): inside/outside agree at " << same << " of " << counted << " cells\n";
  return double(same) / double(counted);
}

TEST(SignedDistance, OpenSphereKeepsTheClosedSpheresInsideAndOutside)
{
  const TriangleMesh sphere = testing::icosphere(4, 1.0);
  EXPECT_GE(agreement(sphere, testing::sdf::withHoles(sphere, 6, 4), 64), 0.999);
}

TEST(SignedDistance, FarFieldIsCloseToExactAndNeverBelowIt)
{
  // Concave corners where the two spheres meet, and a box beside them.
  const TriangleMesh mesh = testing::merged(
      testing::merged(testing::icosphere(3, 0.6, {-0.3, 0, 0}), testing::icosphere(3, 0.5, {0.4, 0.1, 0})),
      testing::box({-0.2, -1.0, -0.3}, {0.3, -0.6, 0.2}));
  const GridFrame frame = frameWithResolution(bounds(mesh), 48, 8);
  SignedDistanceStats stats;
  const Volume fast = signedDistance(mesh, frame, {}, &stats);
  SignedDistanceOptions exactOptions;
  exactOptions.exactEverywhere = true;
  const Volume exact = signedDistance(mesh, frame, exactOptions);
  double worst = 0.0;
  size_t off = 0;
  for (size_t i = 0; i < fast.size(); ++i) {
    ASSERT_EQ(fast[i] > 0, exact[i] > 0);
    const double excess = std::abs(fast[i]) - std::abs(exact[i]);
    ASSERT_GE(excess, -1e-4) << "cell " << i;
    worst = std::max(worst, excess);
    off += excess > kExact;
  }
  std::cout << "far field: " << stats.farCells << " cells, worst excess over exact " << worst << " voxel, " << off
            << " cells off by more than " << kExact << "\n";
  EXPECT_LT(worst, 0.15);
}

TEST(SignedDistance, ResultDoesNotDependOnThreadCount)
{
  // Open (the sign's flood, each level's evaluations on every thread) and
  // closed (its regions, labelled on all threads at once).
  for (const TriangleMesh& mesh :
       {testing::merged(testing::sdf::withHoles(testing::icosphere(3, 1.0), 20, 5),
                        testing::icosphere(2, 0.5, {0.8, 0, 0})),
        testing::merged(testing::icosphere(3, 1.0), testing::icosphere(2, 0.5, {0.8, 0, 0}))}) {
    const GridFrame frame = frameWithResolution(bounds(mesh), 40, 3);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const Volume one = signedDistance(mesh, frame);
    omp_set_num_threads(std::max(threads, 4));
    const Volume many = signedDistance(mesh, frame);
    omp_set_num_threads(threads);
    ASSERT_EQ(one.size(), many.size());
    for (size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], many[i]) << "cell " << i;
  }
}

TEST(SignedDistance, FrameBesideTheMeshStillMeasuresAndSigns)
{
  // The grid starts 0.4 (about 5 voxels) beyond the sphere: no cell is in
  // the band, and the far field must start from scratch.
  const TriangleMesh sphere = testing::icosphere(3, 1.0);
  const GridFrame frame = frameWithResolution(Bounds{{1.4, -1.0, -1.0}, {3.4, 1.0, 1.0}}, 24, 0);
  SignedDistanceStats stats;
  const Volume sdf = signedDistance(sphere, frame, {}, &stats);
  EXPECT_EQ(stats.bandCells, 0u);
  EXPECT_EQ(stats.farCells, stats.cells);
  double worst = 0.0;
  for (size_t i = 0; i < sdf.size(); ++i) {
    const double truth = testing::sdf::bruteForceDistance(sphere, centreOf(frame, i)) / frame.voxel;
    ASSERT_LT(sdf[i], 0.0f);
    ASSERT_GE(-sdf[i], truth - 1e-4);
    worst = std::max(worst, -sdf[i] - truth);
  }
  EXPECT_LT(worst, 0.1);
}

TEST(SignedDistance, GridCroppingTheMeshMeasuresTheWholeMesh)
{
  // The box's face x = -1 lies beyond the grid and more than the band away
  // from it, yet it is the nearest face of the cells along the grid's x = -0.5
  // side: the distances there must still come from it.
  const glm::dvec3 lo(-1.0, -1.0, -1.0), hi(1.0, 1.0, 1.0);
  const TriangleMesh mesh = testing::box(lo, hi);
  const GridFrame frame = frameWithResolution(Bounds{{-0.5, -1.3, -1.3}, {1.3, 1.3, 1.3}}, 28, 0);
  ASSERT_GT((frame.origin.x - lo.x) / frame.voxel, kBand + 1.0);
  const Volume sdf = signedDistance(mesh, frame);
  double worst = 0.0;
  for (size_t i = 0; i < sdf.size(); ++i)
    worst = std::max(worst, std::abs(sdf[i] - boxDistance(centreOf(frame, i), lo, hi) / frame.voxel));
  EXPECT_LT(worst, 1e-3);
}

TEST(SignedDistance, StatsAddUp)
{
  const TriangleMesh sphere = testing::icosphere(3, 1.0);
  const GridFrame frame = frameWithResolution(bounds(sphere), 32, 3);
  SignedDistanceStats stats;
  signedDistance(sphere, frame, {}, &stats);
  EXPECT_EQ(stats.cells, frame.extent.cells());
  EXPECT_EQ(stats.triangles, sphere.triangles.size());
  EXPECT_EQ(stats.bandCells + stats.farCells, stats.cells);
  EXPECT_GT(stats.windingEvaluations, 0u);
  EXPECT_EQ(stats.openEdges, 0u);
  EXPECT_GE(stats.totalMs, stats.bvhMs + stats.bandMs + stats.signMs + stats.farFieldMs - 1e-6);
}

TEST(SignedDistance, RejectsWhatItCannotMeasure)
{
  const TriangleMesh sphere = testing::icosphere(1, 1.0);
  const GridFrame frame = frameWithResolution(bounds(sphere), 16, 2);
  EXPECT_THROW(signedDistance(TriangleMesh{}, frame), InputError);
  TriangleMesh broken = sphere;
  broken.triangles[3].y = 1000;
  EXPECT_THROW(signedDistance(broken, frame), InputError);
  SignedDistanceOptions thin;
  thin.bandVoxels = 0.5;
  EXPECT_THROW(signedDistance(sphere, frame, thin), UsageError);
  GridFrame empty = frame;
  empty.extent = Extent3{0, 4, 4};
  EXPECT_THROW(signedDistance(sphere, empty), UsageError);
}

}  // namespace
}  // namespace lbmshape
