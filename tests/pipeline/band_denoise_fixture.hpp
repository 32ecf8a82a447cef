// The fixture of the band-versus-grid denoise tests (band_denoise_test.cpp,
// and shared_band_denoise_test.cpp on the shared meshes): a mesh denoised on
// the narrow band and on the grid gives the same result.
#pragma once

#include <filesystem>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "support/scratch_folder.hpp"

namespace lbmshape::testing {

struct BandCase {
  std::string name;
  Smoothing smoothing;
  int steps;
  bool twicing = false;
};

inline void PrintTo(const BandCase& c, std::ostream* out) { *out << c.name; }

class BandDenoise : public ::testing::TestWithParam<BandCase> {
protected:
  ComputeDevice device{"", true};  // Vulkan, with the validation layer
  ScratchFolder folder;

  // Band and grid results for a mesh agree within `toleranceVoxels` (mean).
  // The paper's anisotropic rule gets twice that: its kappa is the change of
  // X over one step divided by gamma, which magnifies the difference
  // between the two schemes (moment form and BGK) step after step. Returns
  // the band's report.
  nlohmann::json compare(const std::filesystem::path& input, int resolution, double toleranceVoxels)
  {
    double hausdorffVoxels = 1.0;
    if (GetParam().smoothing == Smoothing::Anisotropic) toleranceVoxels *= 2.0, hausdorffVoxels *= 2.0;
    DenoiseOptions options;
    options.grid.resolution = resolution;
    options.smoothing = GetParam().smoothing;
    options.steps = GetParam().steps;
    options.twicing = GetParam().twicing;
    const DenoiseResult band = denoiseFile(input, folder / "band.glb", options, device);
    options.dense = true;
    const DenoiseResult grid = denoiseFile(input, folder / "grid.glb", options, device);
    const double voxel = grid.report["grid"]["voxel"].get<double>();
    const SurfaceComparison c = compareSurfaces(band.mesh, grid.mesh, ComparisonOptions{30000});
    RecordProperty("mean_voxels", std::to_string(c.mean / voxel));
    RecordProperty("hausdorff_voxels", std::to_string(c.hausdorff / voxel));
    EXPECT_LT(c.mean / voxel, toleranceVoxels);
    EXPECT_LT(c.hausdorff / voxel, hausdorffVoxels);
    const MeshTopology t = analyzeTopology(band.mesh);
    EXPECT_TRUE(t.closedManifold);
    // The anisotropic rule can pinch off a speck of a voxel on one lattice
    // and not the other: its component count is not compared.
    if (GetParam().smoothing != Smoothing::Anisotropic) {
      EXPECT_EQ(t.components, analyzeTopology(grid.mesh).components);
    }
    EXPECT_EQ(band.report["lattice"]["kind"], "band");
    EXPECT_EQ(grid.report["lattice"]["kind"], "grid");
    return band.report;
  }
};

inline std::string bandCaseName(const ::testing::TestParamInfo<BandCase>& info) { return info.param.name; }

}  // namespace lbmshape::testing

#define LBMSHAPE_BAND_DENOISE_MODES(Suite)                                                                \
  INSTANTIATE_TEST_SUITE_P(                                                                               \
      Modes, Suite,                                                                                       \
      ::testing::Values(                                                                                  \
          ::lbmshape::testing::BandCase{"isotropic", ::lbmshape::Smoothing::Isotropic, 7},                \
          ::lbmshape::testing::BandCase{"isotropic_40_steps", ::lbmshape::Smoothing::Isotropic, 40},      \
          ::lbmshape::testing::BandCase{"preserve_features", ::lbmshape::Smoothing::PreserveFeatures, 7}, \
          ::lbmshape::testing::BandCase{"anisotropic", ::lbmshape::Smoothing::Anisotropic, 7},            \
          ::lbmshape::testing::BandCase{"twiced", ::lbmshape::Smoothing::PreserveFeatures, 8, true}),     \
      ::lbmshape::testing::bandCaseName)
