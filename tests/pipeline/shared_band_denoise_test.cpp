// Denoise on the narrow band gives the grid's result on the shared meshes
// at denoise's default grid: within 0.05 voxel (mean), every mode.
#include <gtest/gtest.h>

#include "support/shared_assets.hpp"

#include "band_denoise_fixture.hpp"

namespace lbmshape {
namespace {

using testing::BandDenoise;

TEST_P(BandDenoise, GivesTheGridsResultOnTheArmadillo)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(armadillo, "armadillo.obj");
  compare(armadillo, 128, 0.05);
}

LBMSHAPE_BAND_DENOISE_MODES(BandDenoise);

// An open scan (its sign from the winding number), at the defaults only:
// the grid's signed distance of a holed scan is slow, every mode would
// cost a minute of the suite.
class BandDenoiseOfAScan : public testing::BandDenoise {};

TEST_P(BandDenoiseOfAScan, GivesTheGridsResult)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(scan, "bunny_scan.obj");
  compare(scan, 128, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Defaults, BandDenoiseOfAScan,
                         ::testing::Values(testing::BandCase{"isotropic", Smoothing::Isotropic, 7}),
                         testing::bandCaseName);

}  // namespace
}  // namespace lbmshape
