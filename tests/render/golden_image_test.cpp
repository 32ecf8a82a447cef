// Whole pictures against golden images drawn earlier (tests/render/golden),
// within a tolerance that lets another conformant driver rasterise edges a
// little differently: a mean difference of at most 1.5 levels of 255, and
// at most 1 % of the pixels off by more than 40. To draw them again after a
// deliberate change: LBMSHAPE_UPDATE_GOLDEN=1 render_tests --gtest_filter='Golden*'
// (the tests then report "skipped", never "passed").
#include <cstdlib>

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include "picture_support.hpp"
#include "lbmshape/render/surface_renderer.hpp"
#include "lbmshape/render/surface_values.hpp"
#include "lbmshape/render/text_overlay.hpp"
#include "support/gpu_fixture.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

using render::Image;

class GoldenImage : public testing::GpuTest {
protected:
  void compare(const Image& image, const std::string& name)
  {
    const std::filesystem::path golden = std::filesystem::path(LBMSHAPE_GOLDEN_IMAGES) / (name + ".png");
    if (const char* update = std::getenv("LBMSHAPE_UPDATE_GOLDEN"); update && std::string(update) == "1") {
      ASSERT_TRUE(stbi_write_png(golden.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4));
      GTEST_SKIP() << "rewrote " << golden;
    }
    const Image expected = testing::readPng(golden);
    ASSERT_EQ(expected.width, image.width);
    ASSERT_EQ(expected.height, image.height);
    double sum = 0.0;
    long far = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
      int worst = 0;
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(int(image.rgba[i + c]) - int(expected.rgba[i + c]));
        sum += d, worst = std::max(worst, d);
      }
      far += worst > 40;
    }
    const double pixels = double(image.width) * image.height;
    EXPECT_LE(sum / (3.0 * pixels), 1.5) << name;
    EXPECT_LE(double(far) / pixels, 0.01) << name;
  }
};

TEST_F(GoldenImage, Sphere)
{
  const TriangleMesh sphere = testing::icosphere(4, 1.0);
  compare(testing::draw(gpu(), testing::plainPicture({&sphere}, 128, 128)), "sphere_front");
}

TEST_F(GoldenImage, CubeFromAbove)
{
  const TriangleMesh cube = testing::box({-1, -0.5, -0.25}, {1, 0.5, 0.25});
  compare(testing::draw(gpu(), testing::plainPicture({&cube}, 128, 128, "iso")), "box_iso");
}

TEST_F(GoldenImage, TorusByCurvatureWithItsLegend)
{
  const TriangleMesh torus = testing::torusMesh(1.0, 0.6, 96, 48);
  const std::vector<double> h = render::vertexMeanCurvature(torus);
  const double scale = render::quantile(h, 0.95, true);
  const render::Legend legend{"mean curvature", -scale, scale, true};
  render::Picture picture = testing::plainPicture({&torus}, 192, 192, "20,50");
  picture.legend = legend;
  for (double v : h) picture.panels[0].colours.push_back(render::legendColour(legend, v));
  const render::Layout layout = render::arrange(picture);
  Image image = render::drawSurfaces(gpu(), picture, layout);
  render::drawLegend(image, *layout.legend, legend, layout.textScale);
  compare(image, "torus_curvature");
}

}  // namespace
}  // namespace lbmshape
