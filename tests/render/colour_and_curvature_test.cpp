// What the colours mean: the maps, the discrete mean curvature against
// shapes whose curvature is known, and the distances to a reference.
#include <cmath>

#include <gtest/gtest.h>

#include "lbmshape/render/colour_map.hpp"
#include "lbmshape/render/surface_values.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape::render {
namespace {

TEST(ColourMap, DivergingIsBlueGreyRedAndSequentialRisesInBrightness)
{
  const glm::vec3 low = divergingColour(-1.0), mid = divergingColour(0.0), high = divergingColour(1.0);
  EXPECT_GT(low.b, low.r);
  EXPECT_GT(high.r, high.b);
  EXPECT_NEAR(mid.r, mid.b, 1e-6f);
  EXPECT_NEAR(mid.r, mid.g, 1e-6f);
  // Beyond the ends, and not-a-number, stay on the map.
  EXPECT_EQ(divergingColour(-7.0), low);
  EXPECT_EQ(divergingColour(7.0), high);
  EXPECT_EQ(divergingColour(std::nan("")), mid);
  float previous = -1.0f;
  for (double t = 0.0; t <= 1.0; t += 0.125) {
    const glm::vec3 c = sequentialColour(t);
    const float luminance = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
    EXPECT_GT(luminance, previous) << t;
    previous = luminance;
  }
}

TEST(ColourMap, TheLegendMapsItsEnds)
{
  const Legend signedScale{"H", -2.0, 2.0, true};
  EXPECT_EQ(legendColour(signedScale, -2.0), divergingColour(-1.0));
  EXPECT_EQ(legendColour(signedScale, 0.0), divergingColour(0.0));
  EXPECT_EQ(legendColour(signedScale, 5.0), divergingColour(1.0));
  const Legend magnitude{"d", 0.0, 4.0, false};
  EXPECT_EQ(legendColour(magnitude, 1.0), sequentialColour(0.25));
}

TEST(MeanCurvature, ASphereOfRadiusRHasOneOverR)
{
  for (double r : {0.5, 2.0, 30.0}) {
    const std::vector<double> h = vertexMeanCurvature(testing::icosphere(4, r, glm::dvec3(3.0, -1.0, 7.0)));
    for (double v : h) EXPECT_NEAR(v * r, 1.0, 0.02) << "r = " << r;
  }
}

TEST(MeanCurvature, ATorusIsConvexOutsideAndSaddleShapedInside)
{
  // Torus with R = 1, r = 0.8: H = (R + 2 r cos v) / (2 r (R + r cos v)),
  // positive on the outer equator (v = 0) and negative on the inner one.
  const double R = 1.0, r = 0.8;
  const TriangleMesh torus = testing::torusMesh(R, r, 96, 48);
  const std::vector<double> h = vertexMeanCurvature(torus);
  int checked = 0;
  for (size_t i = 0; i < torus.vertexCount(); ++i) {
    const glm::dvec3 p = torus.positions[i];
    const double rho = std::hypot(p.x, p.y), cosV = (rho - R) / r;
    if (std::abs(p.z) > 0.1 * r) continue;  // near the equators only
    const double expected = (R + 2 * r * cosV) / (2 * r * (R + r * cosV));
    EXPECT_NEAR(h[i], expected, 0.08 * std::abs(expected) + 0.02) << "rho " << rho;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(MeanCurvature, AVertexWithNoAreaAroundItHasNone)
{
  TriangleMesh mesh = testing::icosphere(2);
  mesh.positions.push_back(glm::dvec3(9.0));  // used by no triangle
  EXPECT_EQ(vertexMeanCurvature(mesh).back(), 0.0);
}

TEST(SurfaceDistance, EachVertexGetsItsDistanceToTheReference)
{
  const TriangleMesh inner = testing::icosphere(3, 1.0), outer = testing::icosphere(5, 1.5);
  const TriangleBvh tree(outer, TriangleBvh::Queries::ClosestOnly);
  for (double d : vertexDistances(inner, tree)) EXPECT_NEAR(d, 0.5, 0.01);
}

TEST(Quantile, IgnoresNonFiniteValuesAndTakesMagnitudesWhenAsked)
{
  EXPECT_EQ(quantile({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 0.5, false), 6.0);
  EXPECT_EQ(quantile({-10, 1, 2, std::nan(""), INFINITY}, 0.95, true), 10.0);
  EXPECT_EQ(quantile({}, 0.5, false), 0.0);
}

}  // namespace
}  // namespace lbmshape::render
