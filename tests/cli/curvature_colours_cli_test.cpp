// --color curvature on denoise and morph: per-vertex COLOR_0 on the
// diverging map, validator-clean, seen by three.js, the scale reported.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/cli_runner.hpp"
#include "support/gltf_validator.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

TEST(CurvatureColours, DenoiseColoursConvexRedAndSaddlesBlue)
{
  testing::ScratchFolder folder;
  // A fat torus: convex outside, saddle-shaped (H < 0) around its hole.
  writeMesh(testing::torusMesh(1.0, 0.8, 96, 48), folder / "torus.obj");
  const testing::CliResult r =
      testing::runLbmshape({"denoise", (folder / "torus.obj").string(), (folder / "out.glb").string(), "--res", "48",
                            "--color", "curvature", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(r.out)["curvature_scale"].get<double>(), 0.0);
  EXPECT_NE(r.err.find("mean curvature"), std::string::npos) << "the scale is printed: " << r.err;
  const auto validation = testing::validateGltf(folder / "out.glb");
  EXPECT_TRUE(validation.passed()) << validation;

  const TriangleMesh read = readMesh(folder / "out.glb");
  ASSERT_EQ(read.colours.size(), read.vertexCount());
  int red = 0, blue = 0;
  for (size_t v = 0; v < read.vertexCount(); ++v) {
    const glm::vec3 c = read.colours[v];
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))) &&
                glm::all(glm::lessThanEqual(c, glm::vec3(1.0f))));
    const double rho = std::hypot(read.positions[v].x, read.positions[v].y);
    if (std::abs(read.positions[v].z) > 0.2) continue;  // the equators
    if (rho > 1.6) red += c.r > c.b + 0.2f;
    if (rho < 0.4) blue += c.b > c.r + 0.2f;
  }
  EXPECT_GT(red, 20) << "outer equator";
  EXPECT_GT(blue, 5) << "inside of the hole";

  const testing::ThreeJsLoad web = testing::loadWithThreeJs(folder / "out.glb");
  ASSERT_TRUE(web.failure.empty()) << web.failure;
  EXPECT_EQ(web.scene["coloured"], 1);
  EXPECT_GE(web.scene["colourRange"][0].get<double>(), 0.0);
  EXPECT_LE(web.scene["colourRange"][1].get<double>(), 1.0);
}

TEST(CurvatureColours, MorphColoursEveryFrameOnTheTargetsScale)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "sphere.obj");
  writeMesh(testing::torusMesh(1.0, 0.4, 48, 24), folder / "torus.obj");
  const testing::CliResult r = testing::runLbmshape(
      {"morph", (folder / "sphere.obj").string(), (folder / "torus.obj").string(), (folder / "frames").string(),
       "--res", "24", "--frames", "3", "--color", "curvature", "--compress", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(r.out)["curvature_scale"].get<double>(), 0.0);
  for (const char* name : {"frame_0000.glb", "frame_0002.glb", "morph.glb"}) {
    const auto validation = testing::validateGltf(folder / "frames" / name);
    EXPECT_TRUE(validation.passed()) << name << ": " << validation;
  }
  const testing::ThreeJsLoad web = testing::loadWithThreeJs(folder / "frames" / "morph.glb");
  ASSERT_TRUE(web.failure.empty()) << web.failure;
  EXPECT_EQ(web.scene["coloured"], 3);
  EXPECT_EQ(readMesh(folder / "frames" / "frame_0001.glb").colours.size(),
            readMesh(folder / "frames" / "frame_0001.glb").vertexCount());
}

TEST(CurvatureColours, FormatsWithoutVertexColoursAreRefusedBeforeAnyWork)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(2), folder / "in.obj");
  const auto before = folder.entries();
  const std::string in = (folder / "in.obj").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"denoise", in, (folder / "out.stl").string(), "--color", "curvature"},
        std::vector<std::string>{"morph", in, in, (folder / "frames").string(), "--format", "stl", "--color",
                                 "curvature"},
        std::vector<std::string>{"denoise", in, (folder / "out.glb").string(), "--color", "rainbow"}}) {
    const testing::CliResult r = testing::runLbmshape(args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--color"), std::string::npos) << r.err;
    EXPECT_EQ(folder.entries(), before);
  }
}

}  // namespace
}  // namespace lbmshape
