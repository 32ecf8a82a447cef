// The signed distance on the narrow band against the grid's: every cell the
// band must hold is held, with the grid's value, and the bricks left out
// are on the grid's side of the surface.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/sdf/band_signed_distance.hpp"
#include "lbmshape/sdf/grid_frame.hpp"
#include "lbmshape/sdf/signed_distance.hpp"
#include "support/test_meshes.hpp"

#include "band_sdf_checks.hpp"

namespace lbmshape {

namespace {

struct BandCase {
  std::string name;
  TriangleMesh mesh;
  int resolution;
};

void PrintTo(const BandCase& c, std::ostream* out) { *out << c.name; }

std::vector<BandCase> cases()
{
  TriangleMesh holed = testing::icosphere(3);
  holed.triangles.resize(holed.triangles.size() - 40);  // an open mesh: the sign comes from the winding number
  // The exact band goes triangle by triangle where triangles span voxels
  // (the box, the holed sphere) and cell by cell where many share one (the
  // fine sphere on a coarse grid, the sphere, the torus): band_distance.cpp
  // picks by cost.
  return {{"sphere", testing::icosphere(4), 48},
          {"fine_sphere_coarse_grid", testing::icosphere(5), 20},
          {"torus", testing::torusMesh(1.0, 0.3, 64, 24), 64},
          {"box_off_centre", testing::box({0.1, 0.2, -0.3}, {1.9, 0.8, 0.4}), 56},
          {"sphere_with_a_hole", holed, 40}};
}

class BandSignedDistance : public ::testing::TestWithParam<BandCase> {};

TEST_P(BandSignedDistance, HoldsTheGridsFieldWhereverTheLatticeNeedsIt)
{
  const BandCase& c = GetParam();
  expectBandHoldsTheGridsField(c.mesh, c.resolution, 5.0);
}

INSTANTIATE_TEST_SUITE_P(Shapes, BandSignedDistance, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

TEST(BandSignedDistanceOptions, AHalfWidthUnderOneVoxelIsAUsageError)
{
  const TriangleMesh mesh = testing::icosphere(2);
  const GridFrame frame = frameWithResolution(bounds(mesh), 24, 3.0);
  EXPECT_THROW(signedDistanceBand(mesh, frame, {.halfWidth = 0.5}), UsageError);
}

}  // namespace
}  // namespace lbmshape
