// The signed distance on the shared test meshes: holes punched into the
// bunny must not change its inside, and the armadillo at 128 cells is the
// speed benchmark (printed, not asserted: timings depend on the machine).
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>

#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/sdf/signed_distance.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
#include "support/shared_assets.hpp"

#include "sdf_fixtures.hpp"

namespace lbmshape {
namespace {

// Cells along the longest side for the brute-force sign check of the scan:
// 32 x 32 x 27 cells x 69k triangles, about 13 s on two cores.
constexpr int kScanResolution = 32;

void print(const std::string& name, const GridFrame& frame, const SignedDistanceStats& s)
{
  std::cout << std::fixed << std::setprecision(1) << name << " (" << s.triangles << " triangles) on "
            << frame.extent.toString() << ": total " << s.totalMs << " ms = bvh " << s.bvhMs << " + band " << s.bandMs
            << " + sign " << s.signMs << " + far field " << s.farFieldMs << "; " << s.bandCells << " band cells, "
            << s.farCells << " far cells, " << s.windingEvaluations << " winding-number evaluations, " << s.openEdges
            << " open edges\n";
}

TEST(SharedMeshSignedDistance, BunnyWithHolesKeepsItsInside)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(path, "bunny.obj");
  const TriangleMesh bunny = readMesh(path);
  const TriangleMesh holey = testing::sdf::withHoles(bunny, 40, 11);
  const GridFrame frame = frameWithResolution(bounds(bunny), 96, 3);
  SignedDistanceStats closedStats, openStats;
  const Volume closed = signedDistance(bunny, frame, {}, &closedStats);
  const Volume open = signedDistance(holey, frame, {}, &openStats);
  print("bunny", frame, closedStats);
  print("bunny with 40 holes", frame, openStats);
  size_t counted = 0, same = 0;
  for (size_t i = 0; i < closed.size(); ++i) {
    if (std::abs(closed[i]) <= 2.0f) continue;
    ++counted;
    same += (closed[i] > 0) == (open[i] > 0);
  }
  std::cout << "inside/outside agree at " << same << " of " << counted << " cells farther than 2 voxels\n";
  EXPECT_GT(openStats.openEdges, 100u);
  EXPECT_GE(double(same) / double(counted), 0.999);
}

// A real scan with five holes, where the winding number varies off the
// surface: the sign must be the brute-force winding number's at every cell
// more than a voxel from the surface. The oracle is TriangleBvh's
// exactWindingNumber (a plain sum of solid angles over all 69k triangles,
// itself checked against an independent formula in triangle_bvh_test.cpp);
// at O(cells x triangles) the grid is kept coarse.
TEST(SharedMeshSignedDistance, ScanWithHolesHasTheBruteForceWindingNumbersSign)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(path, "bunny_scan.obj");
  const TriangleMesh scan = readMesh(path);
  const GridFrame frame = frameWithResolution(bounds(scan), kScanResolution, 3);
  SignedDistanceStats stats;
  const Volume sdf = signedDistance(scan, frame, {}, &stats);
  const TriangleBvh bvh(scan);
  const Extent3& e = frame.extent;
  size_t compared = 0, undecided = 0, inside = 0, wrong = 0;
  double nearestToHalf = 1.0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : compared, undecided, inside, wrong) reduction(min : nearestToHalf)
  for (size_t i = 0; i < sdf.size(); ++i) {
    if (std::abs(sdf[i]) <= 1.0f) continue;
    // A quarter of the cells, every fourth along each diagonal plane, so
    // that every part of the grid is still compared (a wrong sign spans a
    // region, never one cell): the brute force costs as much as the rest of
    // CI's shared tests.
    if ((i % e.nx + i / e.nx % e.ny + i / e.nx / e.ny) % 4 != 0) continue;
    const double w =
        bvh.exactWindingNumber(frame.cellCentre(int(i % e.nx), int(i / e.nx % e.ny), int(i / e.nx / e.ny)));
    // Within the fast evaluation's accuracy of 1/2 either sign is right.
    if (std::abs(w - 0.5) < 1e-3) {
      ++undecided;
      continue;
    }
    ++compared;
    inside += w > 0.5;
    wrong += (sdf[i] > 0.0f) != (w > 0.5);
    nearestToHalf = std::min(nearestToHalf, std::abs(w - 0.5));
  }
  print("bunny_scan", frame, stats);
  std::cout << "sign against the brute-force winding number: " << wrong << " wrong of " << compared
            << " cells farther than a voxel (" << inside << " inside, " << undecided
            << " within 1e-3 of 1/2); closest to 1/2 compared: " << std::defaultfloat << std::setprecision(3)
            << nearestToHalf << "\n";
  EXPECT_GT(stats.openEdges, 100u) << "the holes are there";
  EXPECT_GT(inside, compared / 50) << "the scan has an inside";
  EXPECT_LT(undecided, compared / 1000);
  EXPECT_EQ(wrong, 0u);
}

TEST(SharedMeshSignedDistance, ArmadilloAt128)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(path, "armadillo.obj");
  const TriangleMesh armadillo = readMesh(path);
  const GridFrame frame = frameWithResolution(bounds(armadillo), 128, 3);
  SignedDistanceStats stats;
  Volume sdf;
  for (int run = 0; run < 3; ++run) {  // the first run also warms the caches
    sdf = signedDistance(armadillo, frame, {}, &stats);
    print("armadillo, run " + std::to_string(run + 1), frame, stats);
  }
  // A sample of band cells against brute force over all 86k triangles.
  const TriangleBvh bvh(armadillo);
  std::mt19937 rng(1);
  int sampled = 0;
  while (sampled < 100) {
    const size_t i = rng() % sdf.size();
    if (std::abs(sdf[i]) > 3.0f) continue;
    const Extent3& e = frame.extent;
    const glm::dvec3 p = frame.cellCentre(int(i % e.nx), int(i / e.nx % e.ny), int(i / e.nx / e.ny));
    EXPECT_NEAR(std::abs(sdf[i]), testing::sdf::bruteForceDistance(armadillo, p) / frame.voxel, 1e-3);
    ++sampled;
  }
}

TEST(SharedMeshSignedDistance, ArmadilloFarFieldAgainstExact)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(path, "armadillo.obj");
  const TriangleMesh armadillo = readMesh(path);
  const GridFrame frame = frameWithResolution(bounds(armadillo), 128, 3);
  SignedDistanceStats fastStats, exactStats;
  const Volume fast = signedDistance(armadillo, frame, {}, &fastStats);
  SignedDistanceOptions exactOptions;
  exactOptions.exactEverywhere = true;
  const Volume exact = signedDistance(armadillo, frame, exactOptions, &exactStats);
  double worst = 0.0, sum = 0.0;
  size_t off = 0, signs = 0;
  for (size_t i = 0; i < fast.size(); ++i) {
    const double excess = std::abs(fast[i]) - std::abs(exact[i]);
    EXPECT_GE(excess, -1e-4);
    worst = std::max(worst, excess);
    sum += excess;
    off += excess > 1e-3;
    signs += (fast[i] > 0) != (exact[i] > 0);
  }
  std::cout << std::setprecision(4) << "armadillo far field: propagated " << fastStats.farFieldMs << " ms, exact "
            << exactStats.farFieldMs << " ms; worst excess " << worst << " voxel, mean " << sum / fast.size() << ", "
            << off << " of " << fast.size() << " cells off by more than 1e-3 voxel\n";
  EXPECT_EQ(signs, 0u);
  EXPECT_LT(worst, 0.25);
}

}  // namespace
}  // namespace lbmshape
