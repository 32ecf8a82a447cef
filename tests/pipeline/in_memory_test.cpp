// The library's in-memory entry points give what the file-based ones write:
// denoiseMesh as denoiseFile, morphMeshes as morphFiles, frame for frame;
// and they check a mesh from a program as a file's is checked.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/mesh/icosphere.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/pipeline/morph.hpp"
#include "lbmshape/pipeline/render_job.hpp"
#include "support/scratch_folder.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

// Largest distance between corresponding vertices (same counts required).
double largestVertexDifference(const TriangleMesh& a, const TriangleMesh& b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.positions.size(); ++i) worst = std::max(worst, glm::length(a.positions[i] - b.positions[i]));
  return worst;
}

TEST(InMemory, DenoiseMeshGivesTheFilesResult)
{
  ComputeDevice device{"", true};
  testing::ScratchFolder folder;
  // OBJ keeps doubles to 17 digits: the file is the mesh.
  const TriangleMesh noisy = addNormalNoise(testing::icosphere(4), 0.3, 3);
  writeMesh(noisy, folder / "noisy.obj");
  DenoiseOptions o;
  o.grid.resolution = 40;
  const DenoiseResult inMemory = denoiseMesh(noisy, "a noisy sphere", o, device);
  const DenoiseResult fromFile = denoiseFile(folder / "noisy.obj", folder / "smooth.obj", o, device);
  ASSERT_EQ(inMemory.mesh.triangles, fromFile.mesh.triangles);
  EXPECT_EQ(largestVertexDifference(inMemory.mesh, fromFile.mesh), 0.0);
  EXPECT_EQ(inMemory.report["steps"], fromFile.report["steps"]);
  // The meshes' figures as the file's report gives them, without its paths.
  nlohmann::json input = fromFile.report["input"], output = fromFile.report["output"];
  input.erase("path");
  output.erase("path");
  EXPECT_EQ(inMemory.report["input"], input);
  EXPECT_EQ(inMemory.report["output"], output);
  EXPECT_EQ(inMemory.report["volume_change"], fromFile.report["volume_change"]);
}

TEST(InMemory, MorphMeshesHandsOverTheFramesMorphFilesWrites)
{
  ComputeDevice device{"", true};
  testing::ScratchFolder folder;
  const TriangleMesh sphere = testing::icosphere(3, 1.0), torus = testing::torusMesh(1.0, 0.45, 64, 32);
  writeMesh(sphere, folder / "sphere.obj");
  writeMesh(torus, folder / "torus.obj");
  MorphOptions o;
  o.grid.resolution = 40;
  o.align = Alignment::None;
  o.format = "obj";
  o.frames = 5;
  o.steps = 40;
  std::vector<int> order;
  std::vector<TriangleMesh> frames;
  const nlohmann::json report = morphMeshes(sphere, torus, o, device, [&](int k, const TriangleMesh& mesh) {
    order.push_back(k);
    frames.push_back(mesh);
  });
  morphFiles(folder / "sphere.obj", folder / "torus.obj", folder / "frames", o, device);
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4}));
  ASSERT_EQ(frames.size(), 5u);
  for (int k = 0; k < o.frames; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.obj", k);
    const TriangleMesh written = readMesh(folder / "frames" / name);
    ASSERT_EQ(frames[size_t(k)].triangles.size(), written.triangles.size()) << "frame " << k;
    // OBJ frames hold the vertices to 9 significant digits.
    EXPECT_LT(largestVertexDifference(frames[size_t(k)], written), 1e-6) << "frame " << k;
  }
  EXPECT_TRUE(report["folder"].is_null());
  EXPECT_TRUE(report["animation"].is_null());
  EXPECT_EQ(report["frames"], 5);
}

// A sphere into a smaller one on a coarse grid, with the steps given: quick,
// and the same on every run.
MorphOptions smallMorph(int frames, int steps)
{
  MorphOptions o;
  o.grid.resolution = 24;
  o.align = Alignment::None;
  o.frames = frames;
  o.steps = steps;
  return o;
}

// A sink that fails stops the morph with its own error, the first one:
// no frame after it is made (a later frame's error would hide the cause).
TEST(InMemory, TheFirstErrorOfTheSinkStopsTheMorph)
{
  ComputeDevice device{"", true};
  const MorphOptions o = smallMorph(6, 30);
  int calls = 0;
  try {
    morphMeshes(testing::icosphere(3), testing::scaled(testing::icosphere(3), 0.7), o, device,
                [&](int k, const TriangleMesh&) {
                  ++calls;
                  throw OutputError("no room for frame " + std::to_string(k));
                });
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_STREQ(e.what(), "no room for frame 0");
  }
  EXPECT_EQ(calls, 1);
}

// A program's own stop request (a Cancel button) stops a morph at its next
// frame with Interrupted, as Ctrl-C stops the command; it stands until the
// program clears it, and then the same morph runs to its end.
TEST(InMemory, AStopTheProgramRequestsEndsTheMorphUntilCleared)
{
  ComputeDevice device{"", true};
  const MorphOptions o = smallMorph(12, 60);
  const TriangleMesh sphere = testing::icosphere(3), smaller = testing::scaled(testing::icosphere(3), 0.7);
  int calls = 0;
  try {
    morphMeshes(sphere, smaller, o, device, [&](int k, const TriangleMesh&) {
      ++calls;
      if (k == 1) interrupt::requestStop();
    });
    FAIL() << "the morph ran to its end";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.signal(), 0);
    EXPECT_EQ(e.code(), ExitCode::Interrupted);
    EXPECT_EQ(std::string(e.what()).rfind("stopped: ", 0), 0u) << e.what();
  }
  EXPECT_GE(calls, 2);
  EXPECT_LT(calls, o.frames);
  EXPECT_THROW(denoiseMesh(sphere, "a sphere", DenoiseOptions{}, device), Interrupted);  // the request stands
  interrupt::clearStopRequest();
  calls = 0;
  morphMeshes(sphere, smaller, o, device, [&](int, const TriangleMesh&) { ++calls; });
  EXPECT_EQ(calls, o.frames);
}

TEST(InMemory, AMeshWithAnIndexOutOfRangeIsAnInputErrorNamingIt)
{
  ComputeDevice device{"", true};
  TriangleMesh broken = testing::icosphere(2);
  broken.triangles[7][1] = uint32_t(broken.positions.size() + 5);
  try {
    denoiseMesh(broken, "the scan", DenoiseOptions{}, device);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the scan"), std::string::npos) << e.what();
  }
  EXPECT_THROW(morphMeshes(testing::icosphere(2), broken, MorphOptions{}, device, {}), InputError);
}

// Every public function that takes a mesh from a program checks it before
// it indexes it (bounds, the noise and the picture read positions by the
// triangles' indices: a segfault, or silently wrong output); test shapes
// and noise refuse values that make no mesh.
TEST(InMemory, TheHelpersRefuseWhatWouldReadOutOfBounds)
{
  TriangleMesh broken = testing::icosphere(1);
  broken.triangles[0].x = 50'000'000;
  EXPECT_THROW(bounds(broken), InputError);
  EXPECT_THROW(addNormalNoise(broken, 0.1, 1), InputError);
  TriangleMesh notANumber = testing::icosphere(1);
  notANumber.positions[3].y = std::nan("");
  EXPECT_THROW(addNormalNoise(notANumber, 0.1, 1), InputError);
  EXPECT_THROW(addNormalNoise(testing::icosphere(1), std::nan(""), 1), UsageError);
  EXPECT_THROW(addNormalNoise(testing::icosphere(1), -0.1, 1), UsageError);
  EXPECT_NO_THROW(addNormalNoise(testing::icosphere(1), 0.0, 1));

  EXPECT_THROW(icosphere(-1), UsageError);
  EXPECT_THROW(icosphere(maxIcosphereSubdivisions + 1), UsageError);
  EXPECT_THROW(icosphere(1, 0.0), UsageError);
  EXPECT_THROW(icosphere(1, 1.0, glm::dvec3(std::nan(""))), UsageError);
  EXPECT_EQ(icosphere(2).triangleCount(), 320u);

  ComputeDevice device{"", true};
  RenderOptions picture;
  picture.size = glm::ivec2(64, 64);
  EXPECT_THROW(drawMeshes({{&broken, "broken"}}, picture, device), InputError);
  EXPECT_THROW(drawMeshes({{&notANumber, "nan"}}, picture, device), InputError);
  EXPECT_THROW(drawMeshes({{nullptr, "nothing"}}, picture, device), UsageError);
  TriangleMesh fewColours = testing::icosphere(1);
  fewColours.colours.assign(3, glm::vec3(1.0f));
  EXPECT_THROW(drawMeshes({{&fewColours, "few colours"}}, picture, device), InputError);
  const TriangleMesh sphere = testing::icosphere(1);
  EXPECT_EQ(drawMeshes({{&sphere, "sphere"}}, picture, device).width, 64);

  testing::ScratchFolder folder;
  EXPECT_THROW(writeMesh(fewColours, folder / "few.ply"), OutputError);
  EXPECT_FALSE(std::filesystem::exists(folder / "few.ply"));
}

}  // namespace
}  // namespace lbmshape
