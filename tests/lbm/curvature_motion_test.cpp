// A distance field diffusing under the lattice moves its zero level set by
// mean curvature. For a sphere X = R0 - r, diffusion gives (until the
// smoothing of the cone tip at the centre reaches the surface)
//     X(r, t) = R0 - r - 2 gamma t / r,   R(t) = (R0 + sqrt(R0^2 - 8 gamma t)) / 2,
// and exactly, with sigma^2 = 2 gamma t,
//     X(r, t) = R0 - [(sigma^2/r + r) erf(r / (sigma sqrt 2)) + sigma sqrt(2/pi) exp(-r^2 / (2 sigma^2))].
#include <array>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "support/backends.hpp"
#include "support/fields.hpp"

namespace lbmshape {
namespace {

constexpr double R0 = 20.0, gamma = 0.2;
constexpr int centre = 48;

double exactField(double r, double t)
{
  const double s2 = 2.0 * gamma * t, s = std::sqrt(s2);
  return R0 - ((s2 / r + r) * std::erf(r / (s * std::numbers::sqrt2)) +
               s * std::sqrt(2.0 / std::numbers::pi) * std::exp(-r * r / (2.0 * s2)));
}

double exactRadius(double t)
{
  double lo = 1.0, hi = R0;  // exactField(lo) > 0 > exactField(hi) for t > 0
  for (int i = 0; i < 100; ++i) {
    double mid = 0.5 * (lo + hi);
    (exactField(mid, t) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double farFieldRadius(double t) { return 0.5 * (R0 + std::sqrt(R0 * R0 - 8.0 * gamma * t)); }

// Zero crossings of X along the six axis rays from the centre, interpolated
// linearly between the last cell inside and the first outside.
std::array<double, 6> axisRadii(const Volume& X)
{
  const std::array<std::array<int, 3>, 6> rays = {
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  std::array<double, 6> radii{};
  for (size_t k = 0; k < rays.size(); ++k) {
    auto value = [&](int d) {
      return double(X.at(centre + d * rays[k][0], centre + d * rays[k][1], centre + d * rays[k][2]));
    };
    for (int d = 0; d < centre - 1; ++d)
      if (value(d) > 0 && value(d + 1) <= 0) {
        radii[k] = d + value(d) / (value(d) - value(d + 1));
        break;
      }
  }
  return radii;
}

class CurvatureMotion : public testing::BackendTest {};

TEST_P(CurvatureMotion, SphereShrinksAsMeanCurvatureFlowPredicts)
{
  const Extent3 extent{96, 96, 96};
  auto solver = this->solver(extent);
  solver->setUniformGamma(gamma);
  solver->initialize(testing::sphereDistance(extent, centre, centre, centre, R0));
  for (int t = 25; t <= 100; t += 25) {
    solver->step(25);
    const Volume X = solver->field();
    for (double measured : axisRadii(X)) {
      EXPECT_NEAR(measured, farFieldRadius(t), 0.1) << "t = " << t;
      EXPECT_NEAR(measured, exactRadius(t), 0.1) << "t = " << t;
    }
    // The surface really moved: by t = 100 it is 2.25 voxels inside R0.
    EXPECT_LT(axisRadii(X)[0], R0 - 0.5 * (R0 - farFieldRadius(t)));
  }
}

LBMSHAPE_ON_BOTH_BACKENDS(CurvatureMotion);

}  // namespace
}  // namespace lbmshape
