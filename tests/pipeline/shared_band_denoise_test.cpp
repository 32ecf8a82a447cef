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

TEST_P(BandDenoise, GivesTheGridsResultOnTheScanWithHoles)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(scan, "bunny_scan.obj");
  compare(scan, 128, 0.05);
}

LBMSHAPE_BAND_DENOISE_MODES(BandDenoise);

}  // namespace
}  // namespace lbmshape
