// The morph refuses an animation that cannot fit in memory before any work,
// from an estimate of its triangles (pipeline/animation_memory): marching
// cubes must cut a surface into about trianglesPerVoxelArea triangles per
// voxel^2, whatever the shape and its size.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/pipeline/animation_memory.hpp"
#include "support/implicit_fields.hpp"
#include "support/test_meshes.hpp"
#include "lbmshape/surface/marching_cubes.hpp"

namespace lbmshape {
namespace {

struct Shape {
  const char* name;
  testing::ImplicitFunction sdf;
  double exactArea;  // voxels^2
};

TEST(AnimationMemory, MarchingCubesMakesTheTrianglesPerVoxelAreaTheEstimateAssumes)
{
  constexpr double pi = std::numbers::pi;
  const glm::dvec3 centre(32.3, 32.6, 32.1);
  const Shape shapes[] = {
      {"sphere of radius 6", [&](const glm::dvec3& p) { return testing::sphereSdf(p, centre, 6.0); }, 4 * pi * 36.0},
      {"sphere of radius 25", [&](const glm::dvec3& p) { return testing::sphereSdf(p, centre, 25.0); }, 4 * pi * 625.0},
      {"torus 20 x 6", [&](const glm::dvec3& p) { return testing::torusSdf(p, centre, 20.0, 6.0); },
       4 * pi * pi * 20.0 * 6.0},
  };
  const GridFrame frame = testing::cubicFrame({65, 65, 65});
  for (const Shape& shape : shapes) {
    const TriangleMesh mesh = extractSurface(testing::sampleImplicit(frame, shape.sdf), frame);
    EXPECT_NEAR(surfaceArea(mesh) / shape.exactArea, 1.0, 0.03) << shape.name << ": the area itself";
    const double perVoxelArea = double(mesh.triangleCount()) / shape.exactArea;
    EXPECT_NEAR(perVoxelArea / trianglesPerVoxelArea, 1.0, 0.15) << shape.name << ": " << perVoxelArea;
  }
}

TEST(AnimationMemory, GrowsWithFramesAndArea)
{
  EXPECT_DOUBLE_EQ(animationBytes(1000.0, 20), 2.0 * animationBytes(1000.0, 10));
  EXPECT_DOUBLE_EQ(animationBytes(2000.0, 10), 2.0 * animationBytes(1000.0, 10));
  EXPECT_GT(animationBytes(1000.0, 1), 1000.0 * trianglesPerVoxelArea * animationBytesPerTriangle)
      << "with a margin for the shapes in between";
}

// A plain morph.glb past 4 GiB is refused before any work, with a frame
// count that fits; one that fits is not. A sphere of radius 1 at a voxel of
// 0.05 is 5,027 voxels^2 of surface: about 15,000 triangles, 362 KB a frame.
TEST(AnimationMemory, AFileGlbCannotHoldIsRefusedUpFront)
{
  const TriangleMesh sphere = testing::icosphere(4, 1.0);
  EXPECT_NO_THROW(checkAnimationFileFits(sphere, sphere, 0.05, 48));
  EXPECT_NO_THROW(checkAnimationFileFits(sphere, sphere, 0.05, 9000)) << "3.2 GB: it may fit";
  try {
    checkAnimationFileFits(sphere, sphere, 0.05, 100000);
    FAIL() << "36 GB in a .glb";
  } catch (const OutputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("past the 4 GiB a .glb holds"), std::string::npos) << message;
    const size_t at = message.find("about ", message.find("holds")) + 6;
    const int fit = std::stoi(message.substr(at));
    EXPECT_GT(fit, 8000) << message;
    EXPECT_LT(fit, 12000) << message;
  }
}

}  // namespace
}  // namespace lbmshape
