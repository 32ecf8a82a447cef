// The narrow band's signed distance on the shared meshes holds the grid's
// field wherever the lattice needs it (band_signed_distance_test.cpp).
#include <gtest/gtest.h>

#include "lbmshape/mesh/mesh_reader.hpp"
#include "support/shared_assets.hpp"

#include "band_sdf_checks.hpp"

namespace lbmshape {

namespace {

class SharedBandSignedDistance : public ::testing::TestWithParam<std::string> {};

TEST_P(SharedBandSignedDistance, HoldsTheGridsField)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(path, GetParam());
  expectBandHoldsTheGridsField(readMesh(path), 128, 9.0);  // denoise's default grid and band
}

INSTANTIATE_TEST_SUITE_P(Meshes, SharedBandSignedDistance,
                         ::testing::Values("bunny.obj", "bunny_scan.obj", "armadillo.obj", "fertility.obj"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

}  // namespace
}  // namespace lbmshape
