// Denoise on the narrow band gives the grid's result: the same mesh within
// 0.05 voxel (mean), for every smoothing mode.
#include <gtest/gtest.h>

#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/test_meshes.hpp"

#include "band_denoise_fixture.hpp"

namespace lbmshape {
namespace {

using testing::BandDenoise;

TEST_P(BandDenoise, GivesTheGridsResultOnATorus)
{
  writeMesh(testing::torusMesh(1.0, 0.35, 96, 32), folder / "torus.obj");
  compare(folder / "torus.obj", 96, 0.05);
}

LBMSHAPE_BAND_DENOISE_MODES(BandDenoise);

}  // namespace
}  // namespace lbmshape
