// lbmshape render and the --preview of denoise and morph, as a user runs
// them: pictures of the right size and content, every bad argument its exit
// code and one line, and no file left behind by a failure.
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb/stb_image.h>

#include "lbmshape/mesh/mesh_writer.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

// Width and height of a PNG file, or {0, 0} when it is not one.
std::pair<int, int> pngSize(const fs::path& file)
{
  int w = 0, h = 0, channels = 0;
  if (!stbi_info(file.c_str(), &w, &h, &channels)) return {0, 0};
  return {w, h};
}

// Share of the picture's pixels that are not the white background.
double coveredShare(const fs::path& file)
{
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(file.c_str(), &w, &h, &channels, 3);
  if (!data) return -1.0;
  long covered = 0;
  for (long i = 0; i < long(w) * h; ++i) covered += data[3 * i] < 250 || data[3 * i + 1] < 250 || data[3 * i + 2] < 250;
  stbi_image_free(data);
  return double(covered) / (double(w) * h);
}

TEST(RenderCli, DrawsAMeshIntoAPngOfTheAskedSize)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "sphere.obj");
  const testing::CliResult r = testing::runLbmshape(
      {"render", (folder / "sphere.obj").string(), (folder / "sphere.png").string(), "--size", "320x200"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(pngSize(folder / "sphere.png"), std::make_pair(320, 200));
  // A unit sphere fills 92 % of the 200-pixel height: pi (0.46 * 200)^2 of 64000 pixels.
  EXPECT_NEAR(coveredShare(folder / "sphere.png"), M_PI * 92.0 * 92.0 / 64000.0, 0.01);
}

TEST(RenderCli, JsonNamesEveryMeshAndThePicture)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(2), folder / "a.obj");
  writeMesh(testing::box({0, 0, 0}, {1, 1, 1}), folder / "b.glb");
  const testing::CliResult r = testing::runLbmshape({"render", (folder / "a.obj").string(), (folder / "b.glb").string(),
                                                     (folder / "ab.png").string(), "--labels", "--color", "curvature",
                                                     "--view", "iso", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "render");
  ASSERT_EQ(j["meshes"].size(), 2u);
  EXPECT_EQ(j["meshes"][1]["triangles"], 12);
  EXPECT_EQ(j["columns"], 2);
  EXPECT_LT(j["legend"]["low"].get<double>(), 0.0);
  const auto [w, h] = pngSize(folder / "ab.png");
  EXPECT_EQ(j["size"][0], w);
  EXPECT_EQ(j["size"][1], h);
  EXPECT_EQ(w, 1024);
  EXPECT_GT(h, 512) << "labels and legend below the two cells";
}

// The reference solver draws nothing: the Vulkan device that drew is named.
TEST(RenderCli, JsonNamesTheDeviceThatDrew)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(2), folder / "a.obj");
  const auto deviceOf = [&](std::vector<std::string> args) {
    const testing::CliResult r = testing::runLbmshape(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out)["device"].get<std::string>();
  };
  const std::string drew =
      deviceOf({"--device", "reference", "--json", "render", (folder / "a.obj").string(), (folder / "a.png").string()});
  EXPECT_EQ(drew, deviceOf({"--json", "render", (folder / "a.obj").string(), (folder / "b.png").string()}));
  EXPECT_EQ(drew.find("reference"), std::string::npos) << drew;
}

TEST(RenderCli, AFolderOfFramesShowsEvenlyChosenFramesFirstAndLastIncluded)
{
  testing::ScratchFolder folder;
  fs::create_directory(folder / "frames");
  for (int k = 0; k < 10; ++k)
    writeMesh(testing::icosphere(1, 0.5 + 0.1 * k), folder / "frames" / ("frame_000" + std::to_string(k) + ".obj"));
  writeMesh(testing::icosphere(1), folder / "frames" / "morph.glb");  // the animation: not a frame
  const testing::CliResult r = testing::runLbmshape(
      {"render", (folder / "frames").string(), (folder / "sheet.png").string(), "--count", "4", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["meshes"].size(), 4u);
  std::vector<std::string> names;
  for (const auto& m : j["meshes"]) names.push_back(fs::path(m["path"].get<std::string>()).filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"frame_0000.obj", "frame_0003.obj", "frame_0006.obj", "frame_0009.obj"}));
  EXPECT_EQ(j["meshes"][0]["label"], "frame_0000.obj") << "one folder: the file's name";

  // Two morphs' folders side by side: each label names its folder too.
  fs::create_directory(folder / "other");
  for (int k : {0, 9}) writeMesh(testing::icosphere(1), folder / "other" / ("frame_000" + std::to_string(k) + ".obj"));
  const testing::CliResult two =
      testing::runLbmshape({"render", (folder / "frames").string(), (folder / "other").string(),
                            (folder / "two.png").string(), "--count", "2", "--labels", "--json"});
  ASSERT_EQ(two.exitCode, 0) << two.err;
  std::vector<std::string> labels;
  const nlohmann::json twoReport = nlohmann::json::parse(two.out);
  for (const auto& m : twoReport["meshes"]) labels.push_back(m["label"]);
  EXPECT_EQ(labels, (std::vector<std::string>{"frames/frame_0000.obj", "frames/frame_0009.obj", "other/frame_0000.obj",
                                              "other/frame_0009.obj"}));
}

// A morph's frame with no triangles (the shape passing through nothing) is
// a valid file: render draws it as an empty panel, as the morph's preview
// does, alone or among the others.
TEST(RenderCli, AFrameWithNoTrianglesIsAnEmptyPanel)
{
  testing::ScratchFolder folder;
  fs::create_directory(folder / "frames");
  writeMesh(testing::icosphere(2), folder / "frames" / "frame_0000.glb");
  writeMesh(TriangleMesh{}, folder / "frames" / "frame_0001.glb", EmptyMesh::Allowed);
  writeMesh(testing::icosphere(2), folder / "frames" / "frame_0002.glb");
  const testing::CliResult r =
      testing::runLbmshape({"render", (folder / "frames").string(), (folder / "sheet.png").string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["meshes"].size(), 3u);
  EXPECT_EQ(j["meshes"][1]["triangles"], 0);
  EXPECT_GT(coveredShare(folder / "sheet.png"), 0.1) << "the two spheres";

  const testing::CliResult alone = testing::runLbmshape(
      {"render", (folder / "frames" / "frame_0001.glb").string(), (folder / "empty.png").string()});
  ASSERT_EQ(alone.exitCode, 0) << alone.err;
  EXPECT_EQ(coveredShare(folder / "empty.png"), 0.0);
}

TEST(RenderCli, AScansOwnColoursShowAsTheyAre)
{
  testing::ScratchFolder folder;
  const TriangleMesh sphere = testing::icosphere(3);
  {
    std::ofstream obj(folder / "red.obj");
    for (const glm::dvec3& p : sphere.positions) obj << "v " << p.x << " " << p.y << " " << p.z << " 0.9 0.1 0.1\n";
    for (const glm::uvec3& t : sphere.triangles) obj << "f " << t.x + 1 << " " << t.y + 1 << " " << t.z + 1 << "\n";
  }
  const testing::CliResult r =
      testing::runLbmshape({"render", (folder / "red.obj").string(), (folder / "red.png").string(), "--size", "64x64"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load((folder / "red.png").c_str(), &w, &h, &channels, 3);
  ASSERT_NE(data, nullptr);
  const unsigned char* centre = data + 3 * (32 * w + 32);
  EXPECT_GT(int(centre[0]), 3 * int(centre[1])) << "red, lit";
  EXPECT_GT(int(centre[0]), 3 * int(centre[2]));
  stbi_image_free(data);
}

struct BadRender {
  const char* name;
  std::vector<std::string> options;
  int exitCode;
  const char* mentions;
  bool badMesh = false;
  const char* picture = "out.png";
};

void PrintTo(const BadRender& c, std::ostream* os) { *os << c.name; }

class RenderBadArguments : public ::testing::TestWithParam<BadRender> {};

TEST_P(RenderBadArguments, ExitCodeOneLineNoPicture)
{
  const BadRender& c = GetParam();
  testing::ScratchFolder folder;
  if (c.badMesh)  // a face of a vertex that is not there (a mesh of no triangles is drawn as an empty panel)
    std::ofstream(folder / "mesh.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
  else
    writeMesh(testing::icosphere(1), folder / "mesh.obj");
  const auto before = folder.entries();
  std::vector<std::string> args = {"render", (folder / "mesh.obj").string()};
  const std::string picture = c.picture[0] == '/' ? std::string(c.picture) : (folder / c.picture).string();
  args.push_back(picture);
  args.insert(args.end(), c.options.begin(), c.options.end());
  const testing::CliResult r = testing::runLbmshape(args);
  EXPECT_EQ(r.exitCode, c.exitCode) << r.err;
  const auto lines = testing::messageLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_NE(lines[0].find(c.mentions), std::string::npos) << lines[0];
  EXPECT_EQ(folder.entries(), before) << "no picture, no temporary file";
  EXPECT_TRUE(r.out.empty());
}

INSTANTIATE_TEST_SUITE_P(
    Table, RenderBadArguments,
    ::testing::Values(
        BadRender{"size_zero", {"--size", "0x0"}, 2, "--size"},
        BadRender{"size_huge", {"--size", "100000x100000"}, 2, "--size"},
        BadRender{"size_too_many_pixels", {"--size", "8192x8192"}, 2, "--size"},
        BadRender{"size_not_a_size", {"--size", "big"}, 2, "--size"},
        BadRender{"unknown_view", {"--view", "sideways"}, 2, "--view"},
        BadRender{"elevation_past_the_pole", {"--view", "0,100"}, 2, "--view"},
        BadRender{"unknown_colour", {"--color", "rainbow"}, 2, "--color"},
        BadRender{"count_zero", {"--count", "0"}, 2, "--count"},
        BadRender{"negative_columns", {"--columns", "-1"}, 2, "--columns"},
        BadRender{"cells_too_small", {"--size", "16x16", "--labels"}, 2, "--size", false},
        BadRender{"not_a_png", {}, 2, ".png", false, "out.jpg"},
        BadRender{"mesh_with_a_bad_index", {}, 3, "mesh.obj", true},
        BadRender{"missing_reference", {"--color", "distance:/nonexistent/ref.obj"}, 3, "ref.obj"},
        BadRender{"unwritable_picture", {}, 4, "/nonexistent-folder/out.png", false, "/nonexistent-folder/out.png"}),
    [](const ::testing::TestParamInfo<BadRender>& info) { return std::string(info.param.name); });

TEST(RenderCli, APictureNeedsAMeshAndAPicture)
{
  const testing::CliResult r = testing::runLbmshape({"render", "only.png"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
}

TEST(Preview, DenoiseDrawsTheInputAndTheResultSideBySide)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "in.obj");
  const testing::CliResult r =
      testing::runLbmshape({"denoise", (folder / "in.obj").string(), (folder / "out.glb").string(), "--res", "32",
                            "--preview", (folder / "cmp.png").string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto [w, h] = pngSize(folder / "cmp.png");
  EXPECT_EQ(w, 1024);
  EXPECT_GT(h, 512);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["preview"], (folder / "cmp.png").string());
  EXPECT_GT(j["ms"]["preview"].get<double>(), 0.0);
}

TEST(Preview, ABadPreviewPathIsRefusedBeforeAnyWork)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(2), folder / "in.obj");
  const auto before = folder.entries();
  for (const auto& [preview, code] :
       {std::pair{(folder / "cmp.jpg").string(), 2}, std::pair{std::string("/nonexistent-folder/cmp.png"), 4}}) {
    const testing::CliResult r = testing::runLbmshape(
        {"denoise", (folder / "in.obj").string(), (folder / "out.glb").string(), "--res", "24", "--preview", preview});
    EXPECT_EQ(r.exitCode, code) << r.err;
    EXPECT_NE(r.err.find("cmp."), std::string::npos) << r.err;
    EXPECT_EQ(folder.entries(), before) << "no mesh either";
  }
}

TEST(Preview, APreviewThatCannotBeWrittenLeavesNoMeshEither)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "in.obj");
  const std::vector<std::string> job = {
      "denoise",   (folder / "in.obj").string(), (folder / "out.glb").string(), "--res", "24", "--compress",
      "--preview", (folder / "cmp.png").string()};
  // The sizes the limit falls between: a small mesh, a larger picture.
  ASSERT_EQ(testing::runLbmshape(job).exitCode, 0);
  const auto meshBytes = fs::file_size(folder / "out.glb"), pictureBytes = fs::file_size(folder / "cmp.png");
  const uintmax_t limitBytes = 20 * 1024;
  ASSERT_LT(meshBytes, limitBytes);
  ASSERT_GT(pictureBytes, limitBytes);
  fs::remove(folder / "out.glb");
  fs::remove(folder / "cmp.png");
  const auto before = folder.entries();

  // A file-size limit fails the picture's write as a full disk would
  // (lbmshape ignores SIGXFSZ: the write returns EFBIG instead of killing).
  const testing::CliResult limited = testing::runLbmshapeWithFileSizeLimit(limitBytes, job);
  EXPECT_EQ(limited.exitCode, 4);
  EXPECT_NE(limited.err.find("cmp.png"), std::string::npos) << limited.err;
  EXPECT_EQ(folder.entries(), before) << "neither the picture nor the mesh";
}

TEST(Preview, MorphDrawsAContactSheetIntoItsOwnFolder)
{
  testing::ScratchFolder folder;
  writeMesh(testing::icosphere(3), folder / "sphere.obj");
  writeMesh(testing::torusMesh(1.0, 0.4, 48, 24), folder / "torus.obj");
  const testing::CliResult r = testing::runLbmshape(
      {"morph", (folder / "sphere.obj").string(), (folder / "torus.obj").string(), (folder / "frames").string(),
       "--res", "24", "--frames", "9", "--no-animation", "--preview", (folder / "frames" / "sheet.png").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // Source, six frames, target: two rows of four cells of 384 pixels.
  const auto [w, h] = pngSize(folder / "frames" / "sheet.png");
  EXPECT_EQ(w, 4 * 384);
  EXPECT_GT(h, 2 * 384);
  EXPECT_GT(coveredShare(folder / "frames" / "sheet.png"), 0.05);
}

}  // namespace
}  // namespace lbmshape
