// --compress on denoise and morph: smaller .glb files that the
// glTF-Validator accepts, refused before any work for other formats.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/cli_runner.hpp"
#include "support/gltf_validator.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

TEST(CompressCli, DenoiseWritesASmallerValidGlb)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(4), folder / "in.obj");
  const std::string in = (folder / "in.obj").string();
  ASSERT_EQ(testing::runLbmshape({"denoise", in, (folder / "plain.glb").string(), "--res", "64"}).exitCode, 0);
  const testing::CliResult r =
      testing::runLbmshape({"denoise", in, (folder / "small.glb").string(), "--res", "64", "--compress"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_LT(fs::file_size(folder / "small.glb") * 3, fs::file_size(folder / "plain.glb"));
  const auto validation = testing::validateGltf(folder / "small.glb");
  EXPECT_TRUE(validation.passed()) << validation;
  // A web viewer sees the same surface in the same place.
  const testing::ThreeJsLoad plain = testing::loadWithThreeJs(folder / "plain.glb");
  const testing::ThreeJsLoad small = testing::loadWithThreeJs(folder / "small.glb");
  ASSERT_TRUE(plain.failure.empty()) << plain.failure;
  ASSERT_TRUE(small.failure.empty()) << small.failure;
  EXPECT_EQ(small.scene["triangles"], plain.scene["triangles"]);
  for (const char* corner : {"min", "max"})
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(small.scene[corner][k].get<double>(), plain.scene[corner][k].get<double>(), 2.0 / 65535.0) << corner;
}

TEST(CompressCli, MorphCompressesItsFramesAndItsAnimation)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "sphere.obj");
  writeMesh(testing::torusMesh(1.0, 0.4, 48, 24), folder / "torus.obj");
  const testing::CliResult r =
      testing::runLbmshape({"morph", (folder / "sphere.obj").string(), (folder / "torus.obj").string(),
                            (folder / "frames").string(), "--res", "24", "--frames", "4", "--compress"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"frame_0000.glb", "frame_0003.glb", "morph.glb"}) {
    const auto validation = testing::validateGltf(folder / "frames" / name);
    EXPECT_TRUE(validation.passed()) << name << ": " << validation;
  }
  const testing::ThreeJsLoad animation = testing::loadWithThreeJs(folder / "frames" / "morph.glb");
  ASSERT_TRUE(animation.failure.empty()) << animation.failure;
  EXPECT_EQ(animation.scene["meshes"], 4);
  EXPECT_EQ(animation.scene["animations"], 1);
  // lbmshape reads its compressed frames back, for render and compare.
  const testing::CliResult sheet =
      testing::runLbmshape({"render", (folder / "frames").string(), (folder / "sheet.png").string(), "--json"});
  ASSERT_EQ(sheet.exitCode, 0) << sheet.err;
  EXPECT_EQ(nlohmann::json::parse(sheet.out)["meshes"].size(), 4u);
}

TEST(CompressCli, OtherFormatsAreRefusedBeforeAnyWork)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(2), folder / "in.obj");
  const auto before = folder.entries();
  const std::string in = (folder / "in.obj").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"denoise", in, (folder / "out.obj").string(), "--compress"},
        std::vector<std::string>{"denoise", in, (folder / "out.gltf").string(), "--compress"},
        std::vector<std::string>{"morph", in, in, (folder / "frames").string(), "--format", "ply", "--compress"}}) {
    const testing::CliResult r = testing::runLbmshape(args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--compress"), std::string::npos) << r.err;
    EXPECT_EQ(testing::nonEmptyLines(r.err).size(), 1u) << r.err;
    EXPECT_EQ(folder.entries(), before);
  }
}

}  // namespace
}  // namespace lbmshape
