// The paper's Fig. 8 and 9 kind of morph on a shared mesh: a noisy sphere
// flows into the bunny.
#include <gtest/gtest.h>

#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/pipeline/morph.hpp"
#include "support/scratch_folder.hpp"
#include "support/shared_assets.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

TEST(SharedMorph, NoisySphereBecomesTheBunny)
{
  LBMSHAPE_REQUIRE_SHARED_ASSET(bunny, "bunny.obj");
  testing::ScratchFolder folder;
  const TriangleMesh target = readMesh(bunny);
  const Bounds box = bounds(target);
  // A sphere in the bunny's place, about as large.
  writeMesh(testing::icosphere(4, 0.4 * box.diagonal() / 2.0, box.centre()), folder / "sphere.obj");
  MorphOptions options;
  options.grid.resolution = 96;
  options.align = Alignment::None;
  options.noise = FieldNoise{0.05, 1};  // the paper's noisy sphere
  ComputeDevice device("", true);
  const nlohmann::json report = morphFiles(folder / "sphere.obj", bunny, folder / "frames", options, device);
  const double voxel = report["grid"]["voxel"];
  const double mean = compareSurfaces(readMesh(folder / "frames" / "frame_0047.glb"), target).mean / voxel;
  RecordProperty("last_frame_mean_distance_voxels", std::to_string(mean));
  EXPECT_LE(mean, 1.0);
}

}  // namespace
}  // namespace lbmshape
