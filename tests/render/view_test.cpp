// --view: the named views, azimuth and elevation, and the camera's axes.
#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/render/view.hpp"

namespace lbmshape::render {
namespace {

void expectNear(const glm::dvec3& a, const glm::dvec3& b)
{
  EXPECT_NEAR(glm::length(a - b), 0.0, 1e-12) << a.x << " " << a.y << " " << a.z;
}

TEST(View, NamedViewsLookAlongTheAxes)
{
  const CameraAxes front = cameraAxes(parseView("front"));
  expectNear(front.towardsViewer, {0, 0, 1});
  expectNear(front.right, {1, 0, 0});
  expectNear(front.up, {0, 1, 0});
  const CameraAxes side = cameraAxes(parseView("side"));
  expectNear(side.towardsViewer, {1, 0, 0});
  expectNear(side.up, {0, 1, 0});
  // Straight down, the picture's up is -Z: the front of the mesh at the bottom.
  const CameraAxes top = cameraAxes(parseView("top"));
  expectNear(top.towardsViewer, {0, 1, 0});
  expectNear(top.up, {0, 0, -1});
  // iso looks along the diagonal (1, 1, 1).
  expectNear(cameraAxes(parseView("iso")).towardsViewer, glm::normalize(glm::dvec3(1.0)));
}

TEST(View, AnyAzimuthAndElevationGiveARightHandedOrthonormalCamera)
{
  for (const char* text : {"0,0", "30,20", "-135.5,-89", "720,90", "13,-90"}) {
    const CameraAxes a = cameraAxes(parseView(text));
    EXPECT_NEAR(glm::length(a.right), 1.0, 1e-12) << text;
    EXPECT_NEAR(glm::length(a.up), 1.0, 1e-12) << text;
    EXPECT_NEAR(glm::dot(a.right, a.up), 0.0, 1e-12) << text;
    EXPECT_NEAR(glm::dot(a.right, a.towardsViewer), 0.0, 1e-12) << text;
    expectNear(glm::cross(a.right, a.up), a.towardsViewer);
    EXPECT_NEAR(a.right.y, 0.0, 1e-12) << "the picture never rolls: " << text;
  }
}

TEST(View, AnythingElseIsAUsageErrorNamingTheOption)
{
  for (const char* text :
       {"", "sideways", "30", "30,", ",20", "30,20,10", "a,b", "30,91", "nan,0", "inf,0", "0,-90.5"}) {
    try {
      parseView(text);
      ADD_FAILURE() << "accepted '" << text << "'";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(nameOf(Parameter::View) + " ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace lbmshape::render
