// The device's pictures against geometry and light worked out on the CPU:
// silhouettes against the analytic projection, pixel colours against
// shading.hpp (the fragment shader's formula), colours by curvature, one
// scale across meshes, wireframes. Under the validation layer (GpuTest).
#include <cmath>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "picture_support.hpp"
#include "lbmshape/render/shading.hpp"
#include "lbmshape/render/surface_values.hpp"
#include "lbmshape/render/surface_renderer.hpp"
#include "support/gpu_fixture.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

using render::Image;

class SurfaceRenderer : public testing::GpuTest {};

constexpr int kSize = 256;
// The union of the meshes' boxes fills 92 % of the cell: a unit sphere's
// radius in pixels.
constexpr double kUnitRadiusPixels = 0.92 * kSize / 2.0;

TEST_F(SurfaceRenderer, ASphereCoversTheDiscOfItsProjection)
{
  const TriangleMesh sphere = testing::icosphere(5, 1.0);
  const Image image = testing::draw(gpu(), testing::plainPicture({&sphere}, kSize, kSize));
  ASSERT_EQ(image.width, kSize);
  const double disc = M_PI * kUnitRadiusPixels * kUnitRadiusPixels;
  double sx = 0, sy = 0;
  long n = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (testing::covered(image, x, y)) sx += x + 0.5, sy += y + 0.5, ++n;
  EXPECT_NEAR(double(n) / disc, 1.0, 0.015);
  EXPECT_NEAR(sx / n, kSize / 2.0, 0.5);
  EXPECT_NEAR(sy / n, kSize / 2.0, 0.5);
}

TEST_F(SurfaceRenderer, ACubeFromTheFrontIsASquare)
{
  const TriangleMesh cube = testing::box({-1, -1, -1}, {1, 1, 1});
  const Image image = testing::draw(gpu(), testing::plainPicture({&cube}, kSize, kSize));
  int lo = kSize, hi = -1;
  for (int x = 0; x < kSize; ++x)
    if (testing::covered(image, x, kSize / 2)) lo = std::min(lo, x), hi = std::max(hi, x);
  EXPECT_NEAR(lo, kSize / 2.0 - kUnitRadiusPixels, 1.0);
  EXPECT_NEAR(hi + 1, kSize / 2.0 + kUnitRadiusPixels, 1.0);
  const double side = 2.0 * kUnitRadiusPixels;
  EXPECT_NEAR(double(testing::coveredPixels(image, {0, 0, kSize, kSize})) / (side * side), 1.0, 0.015);
}

TEST_F(SurfaceRenderer, AMeshLooksTheSameAtAnyScaleADoubleHolds)
{
  // The GPU draws in floats: a cube 6e38 across overflowed them, one 2e-40
  // across became denormals flushed to zero, and both drew a blank picture.
  const TriangleMesh unit = testing::box({-1, -1, -1}, {1, 1, 1});
  const Image reference = testing::draw(gpu(), testing::plainPicture({&unit}, kSize, kSize));
  for (const double scale : {3e38, 1e-40}) {
    TriangleMesh scaled = unit;
    for (glm::dvec3& p : scaled.positions) p = p * scale + glm::dvec3(5.0 * scale);
    const Image image = testing::draw(gpu(), testing::plainPicture({&scaled}, kSize, kSize));
    ASSERT_EQ(image.rgba.size(), reference.rgba.size());
    long differing = 0;
    for (size_t i = 0; i < image.rgba.size(); ++i)
      differing += std::abs(int(image.rgba[i]) - int(reference.rgba[i])) > 2;
    EXPECT_EQ(differing, 0) << "a cube " << 2.0 * scale << " across";
    EXPECT_GT(testing::coveredPixels(image, {0, 0, kSize, kSize}), kSize * kSize / 2) << scale;
  }
}

TEST_F(SurfaceRenderer, PixelsAreLitAsTheCpuReferenceLightsTheirNormal)
{
  const TriangleMesh sphere = testing::icosphere(5, 1.0);
  const Image image = testing::draw(gpu(), testing::plainPicture({&sphere}, kSize, kSize));
  double worst = 0.0, sum = 0.0;
  int n = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      // The sphere's normal where the pixel's centre meets it (view space: y up).
      const double u = (x + 0.5 - kSize / 2.0) / kUnitRadiusPixels, v = -(y + 0.5 - kSize / 2.0) / kUnitRadiusPixels;
      if (u * u + v * v > 0.85 * 0.85) continue;
      const glm::dvec3 expected =
          render::shade(glm::dvec3(render::plainSurfaceColour()), {u, v, std::sqrt(1 - u * u - v * v)});
      const glm::dvec3 drawn = glm::dvec3(image.colour(x, y));
      const double difference = glm::length(drawn - expected) * 255.0;
      worst = std::max(worst, difference), sum += difference, ++n;
    }
  EXPECT_LT(worst, 10.0) << "levels of 255";
  EXPECT_LT(sum / n, 2.0) << "levels of 255";
}

TEST_F(SurfaceRenderer, TheBackOfAnOpenSurfaceIsLitLikeItsFront)
{
  // One square facing away from the viewer (wound clockwise as seen).
  TriangleMesh square;
  square.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  square.triangles = {{0, 2, 1}, {0, 3, 2}};
  const Image image = testing::draw(gpu(), testing::plainPicture({&square}, 64, 64));
  const glm::dvec3 expected = render::shade(glm::dvec3(render::plainSurfaceColour()), {0, 0, 1});
  EXPECT_LT(glm::length(glm::dvec3(image.colour(32, 32)) - expected) * 255.0, 2.0);
}

TEST_F(SurfaceRenderer, CurvatureColoursShowConvexRedAndSaddleBlue)
{
  // Torus R = 1, r = 0.8 seen along its axis: the outer equator is convex
  // (H > 0), the inside of the hole saddle-shaped with H < 0.
  const TriangleMesh torus = testing::torusMesh(1.0, 0.8, 128, 64);
  const std::vector<double> h = render::vertexMeanCurvature(torus);
  const double scale = render::quantile(h, 0.95, true);
  const render::Legend legend{"H", -scale, scale, true};
  render::Picture picture = testing::plainPicture({&torus}, kSize, kSize);
  for (double v : h) picture.panels[0].colours.push_back(render::legendColour(legend, v));
  const Image image = testing::draw(gpu(), picture);
  const double pixelsPerUnit = 0.92 * kSize / 2.0 / 1.8;  // the torus spans 1.8 either side
  const auto at = [&](double rho) { return image.colour(int(kSize / 2.0 + rho * pixelsPerUnit), kSize / 2); };
  const glm::vec3 outer = at(1.7), inner = at(0.25);
  EXPECT_GT(outer.r, outer.b + 0.1f) << "convex: red";
  EXPECT_GT(inner.b, inner.r + 0.1f) << "saddle with H < 0: blue";
}

TEST_F(SurfaceRenderer, MeshesSideBySideShareOneScale)
{
  const TriangleMesh big = testing::icosphere(5, 1.0), small = testing::icosphere(5, 0.5);
  const render::Picture picture = testing::plainPicture({&big, &small}, 2 * kSize, kSize);
  const Image image = testing::draw(gpu(), picture);
  const render::Layout layout = render::arrange(picture);
  const double ratio = double(testing::coveredPixels(image, layout.meshCells[0])) /
                       double(testing::coveredPixels(image, layout.meshCells[1]));
  EXPECT_NEAR(ratio, 4.0, 0.1) << "areas go with the square of the radius";
}

TEST_F(SurfaceRenderer, AWireframeDrawsTheEdgesOverTheSurface)
{
  if (!gpu().canDrawLines()) GTEST_SKIP() << "this device draws no lines (fillModeNonSolid)";
  const TriangleMesh coarse = testing::icosphere(1, 1.0);
  render::Picture picture = testing::plainPicture({&coarse}, kSize, kSize);
  const auto linePixels = [&](const Image& image) {
    long n = 0;
    const glm::dvec3 line = render::lineColour();
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) n += glm::length(glm::dvec3(image.colour(x, y)) - line) < 0.05;
    return n;
  };
  EXPECT_EQ(linePixels(testing::draw(gpu(), picture)), 0);
  picture.wireframe = true;
  const Image wires = testing::draw(gpu(), picture);
  // 120 edges, each tens of pixels long, the front half visible.
  EXPECT_GT(linePixels(wires), 1000);
  EXPECT_LT(linePixels(wires), kSize * kSize / 4);
}

TEST_F(SurfaceRenderer, EdgesAreAntialiased)
{
  const TriangleMesh sphere = testing::icosphere(5, 1.0);
  const Image image = testing::draw(gpu(), testing::plainPicture({&sphere}, kSize, kSize));
  if (render::samplesPerPixel(gpu()) == 1) GTEST_SKIP() << "this device has no 4-sample framebuffers";
  // Along the silhouette, a pixel part covered lies between the surface
  // just inside it and the background.
  const auto luminance = [](glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; };
  long blended = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double dx = x + 0.5 - kSize / 2.0, dy = y + 0.5 - kSize / 2.0, r = std::hypot(dx, dy);
      if (std::abs(r - kUnitRadiusPixels) > 0.7) continue;
      const double inward = (r - 3.0) / r;
      const float inside = luminance(image.colour(int(kSize / 2.0 + dx * inward), int(kSize / 2.0 + dy * inward)));
      const float here = luminance(image.colour(x, y));
      if (here > inside + 0.1f * (1.0f - inside) && here < 1.0f - 0.1f * (1.0f - inside)) ++blended;
    }
  EXPECT_GT(blended, 150);
}

TEST_F(SurfaceRenderer, APictureLargerThanTheDeviceDrawsIsADeviceError)
{
  const TriangleMesh sphere = testing::icosphere(1);
  const int tooWide = int(std::min(gpu().limits().maxFramebufferWidth, gpu().limits().maxImageDimension2D)) + 1;
  EXPECT_THROW(testing::draw(gpu(), testing::plainPicture({&sphere}, tooWide, 16)), DeviceError);
}

}  // namespace
}  // namespace lbmshape
