// The denoise command on the shared test meshes, held to the figures of
// issue 3: a clean mesh barely moves, noise goes, a scan with holes comes out
// closed, and --preserve-features keeps the fandisk's edges better than
// isotropic smoothing. Distances are in voxels of the grid used.
#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "support/scratch_folder.hpp"
#include "support/shared_assets.hpp"

namespace lbmshape {
namespace {

class SharedDenoise : public ::testing::Test {
protected:
  ComputeDevice device{"", true};
  testing::ScratchFolder folder;

  DenoiseResult denoise(const std::filesystem::path& input, const DenoiseOptions& options = {})
  {
    return denoiseFile(input, folder / "out.glb", options, device);
  }
  // A noisy copy made by `lbmshape noise`'s code, as a user would make one.
  std::filesystem::path noisy(const std::filesystem::path& clean, double sigma, uint32_t seed)
  {
    auto path = folder / ("noisy-" + clean.stem().string() + ".obj");
    writeMesh(addNormalNoise(readMesh(clean), sigma, seed), path);
    return path;
  }
  static double voxel(const DenoiseResult& r) { return r.report["grid"]["voxel"].get<double>(); }
};

TEST_F(SharedDenoise, CleanBunnyBarelyMoves)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(bunny, "bunny.obj");
  const DenoiseResult r = denoise(bunny);  // 128^3, 7 steps, gamma 0.2
  const double mean = compareSurfaces(readMesh(bunny), r.mesh).mean / voxel(r);
  RecordProperty("mean_distance_voxels", std::to_string(mean));
  EXPECT_LE(mean, 0.5);
  EXPECT_TRUE(analyzeTopology(r.mesh).closedManifold);
}

TEST_F(SharedDenoise, NoisyArmadilloLosesItsNoise)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(armadillo, "armadillo.obj");
  const TriangleMesh clean = readMesh(armadillo);
  const auto noisyPath = noisy(armadillo, 0.5, 7);
  const DenoiseResult r = denoise(noisyPath);
  const double noisyError = compareSurfaces(clean, readMesh(noisyPath)).meanNormalAngle;
  const SurfaceComparison denoised = compareSurfaces(clean, r.mesh);
  RecordProperty("noisy_normal_error_deg", std::to_string(noisyError));
  RecordProperty("denoised_normal_error_deg", std::to_string(denoised.meanNormalAngle));
  EXPECT_LE(denoised.meanNormalAngle, 0.5 * noisyError);
  EXPECT_LE(denoised.mean / voxel(r), 0.5);
}

TEST_F(SharedDenoise, ScanWithHolesBecomesOneClosedSurface)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(scan, "bunny_scan.obj");
  const DenoiseResult r = denoise(scan);
  const MeshTopology t = analyzeTopology(r.mesh);
  EXPECT_TRUE(t.closedManifold);
  EXPECT_EQ(t.components, 1u);
  const double mean = compareSurfaces(readMesh(scan), r.mesh).mean / voxel(r);
  RecordProperty("mean_distance_voxels", std::to_string(mean));
  EXPECT_LE(mean, 0.5);
}

// Vertex noise of 0.2 and 0.3 mean edge lengths (0.5 and 0.7 voxels at this
// grid): noise that leaves the edges recognisable, where keeping them is what
// matters. The paper's --anisotropic rule is measured and reported too.
class FandiskFeatures : public SharedDenoise, public ::testing::WithParamInterface<double> {};

TEST_P(FandiskFeatures, PreserveFeaturesBeatsIsotropic)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(fandisk, "fandisk.obj");
  const TriangleMesh clean = readMesh(fandisk);
  const auto input = noisy(fandisk, GetParam(), 3);
  auto normalError = [&](Smoothing mode) {
    DenoiseOptions options;
    options.smoothing = mode;
    options.steps = 7;  // the rules compared over the same steps (docs/denoising.md's table)
    return compareSurfaces(clean, denoise(input, options).mesh).meanNormalAngle;
  };
  const double isotropic = normalError(Smoothing::Isotropic);
  const double preserving = normalError(Smoothing::PreserveFeatures);
  const double paper = normalError(Smoothing::Anisotropic);
  RecordProperty("isotropic_deg", std::to_string(isotropic));
  RecordProperty("preserve_features_deg", std::to_string(preserving));
  RecordProperty("paper_anisotropic_deg", std::to_string(paper));
  std::cout << "fandisk, noise " << GetParam() << " edge lengths: mean normal error isotropic " << isotropic
            << " deg, --preserve-features " << preserving << " deg, --anisotropic (paper) " << paper << " deg\n";
  EXPECT_LT(preserving, 0.97 * isotropic);
}

INSTANTIATE_TEST_SUITE_P(Noise, FandiskFeatures, ::testing::Values(0.2, 0.3),
                         [](const auto& info) { return "sigma_0_" + std::to_string(int(info.param * 10)); });

}  // namespace
}  // namespace lbmshape
