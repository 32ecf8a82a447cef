// The per-cell gamma of --anisotropic (the paper's Eq. 20) and
// --preserve-features, on fields whose curvature is known exactly. These run
// on the CPU reference solver: the rules are CPU code, and the Vulkan solver
// is held to the reference elsewhere (gpu_matches_reference_test.cpp).
//
// What the paper's kappa is. Eq. 19 defines kappa = div(grad X / |grad X|),
// and Eq. 20 reads it off one step as (X(n+1) - X(n)) / gamma(n) = Laplacian X
// when |grad X| = 1. For a sphere of radius R with X = R - r (positive inside)
// that is -2/r: the sum of the two principal curvatures, not their mean 1/R,
// and negative on a convex surface.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "lbmshape/lbm/adaptive_gamma.hpp"
#include "lbmshape/lbm/band_reference_solver.hpp"
#include "lbmshape/lbm/reference_solver.hpp"
#include "support/band_fields.hpp"
#include "support/fields.hpp"

namespace lbmshape {
namespace {

constexpr double gamma0 = 0.2;  // the paper's Armadillo and lbmshape's default

// Eq. 20 on the step after `warmSteps` steps of uniform gamma0, returned as
// kappa per cell (paperRule's gamma0 + kappa, minus gamma0; the offset keeps
// gamma0 + kappa inside the clamp range for the curvatures used here).
Volume paperKappa(const Volume& field, int warmSteps)
{
  ReferenceSolver solver(field.extent());
  solver.setUniformGamma(gamma0);
  solver.initialize(field);
  solver.step(warmSteps);
  const Volume before = solver.field();
  solver.step(1);
  const Volume after = solver.field();
  constexpr double offset = 0.5;
  Volume kappa = adaptive_gamma::paperRule(before, after, Volume(field.extent(), float(gamma0)), offset);
  for (size_t i = 0; i < kappa.size(); ++i) kappa[i] -= float(offset);
  return kappa;
}

struct SphereCase {
  Extent3 extent{48, 48, 48};
  double centre = 23.5, radius = 10.0;
  double r(int x, int y, int z) const { return glm::length(glm::dvec3(x, y, z) - glm::dvec3(centre)); }
};

TEST(PaperRule, KappaOfASphereIsMinusTwoOverItsRadius)
{
  const SphereCase s;
  // Past the start-up transient (it decays like (1 - 1/tau)^t = 0.09^t at
  // gamma0 = 0.2; PaperRule.FirstStepKappaIsScaledByTheStartUpTransient).
  // Meanwhile X = R - r - 2 gamma t / r, whose Laplacian is still -2/r.
  const Volume before = testing::sphereDistance(s.extent, s.centre, s.centre, s.centre, s.radius);
  const Volume kappa = paperKappa(before, 6);
  int surfaceCells = 0;
  double sum = 0.0;
  for (int z = 0; z < s.extent.nz; ++z)
    for (int y = 0; y < s.extent.ny; ++y)
      for (int x = 0; x < s.extent.nx; ++x) {
        if (std::abs(before.at(x, y, z)) >= 0.5) continue;  // the cells the surface passes through
        const double expected = -2.0 / s.r(x, y, z);
        EXPECT_NEAR(kappa.at(x, y, z), expected, 0.02 * std::abs(expected)) << "cell " << x << ' ' << y << ' ' << z;
        sum += kappa.at(x, y, z);
        ++surfaceCells;
      }
  ASSERT_GT(surfaceCells, 1000);
  // On average, -2/R: twice the mean curvature 1/R, negative where convex.
  EXPECT_NEAR(sum / surfaceCells, -2.0 / s.radius, 0.01 * 2.0 / s.radius);
}

TEST(PaperRule, FirstStepKappaIsScaledByTheStartUpTransient)
{
  // Started in equilibrium, the first step moves X by Laplacian(X) / 6
  // whatever tau is (docs/lattice-theory.md, "Initialisation"), so Eq. 20 on
  // that step reads kappa / (6 gamma0): 5/6 of it at gamma0 = 0.2. The
  // --anisotropic rule uses this first kappa as the paper writes it;
  // docs/denoising.md says so.
  const SphereCase s;
  const Volume field = testing::sphereDistance(s.extent, s.centre, s.centre, s.centre, s.radius);
  const Volume kappa = paperKappa(field, 0);
  const int x = int(s.centre + s.radius), y = int(s.centre), z = int(s.centre);  // next to the surface on the x axis
  const double expected = -2.0 / s.r(x, y, z) / (6.0 * gamma0);
  EXPECT_NEAR(kappa.at(x, y, z), expected, 0.02 * std::abs(expected));
}

TEST(PaperRule, GammaStaysInTheStableRangeOnANoisyField)
{
  // Noise of +-2 voxels makes Eq. 20's kappa range far beyond [-1, 1], so
  // both ends of the clamp are reached.
  const Extent3 extent{20, 18, 16};
  const Volume before = testing::randomField(extent, -2.0f, 2.0f, 7);
  ReferenceSolver solver(extent);
  solver.setUniformGamma(gamma0);
  solver.initialize(before);
  solver.step(1);
  const Volume gamma = adaptive_gamma::paperRule(before, solver.field(), Volume(extent, float(gamma0)), gamma0);
  const auto [lo, hi] = std::minmax_element(gamma.values().begin(), gamma.values().end());
  EXPECT_GE(*lo, float(adaptive_gamma::lowest));
  EXPECT_LE(*hi, float(adaptive_gamma::highest));
  EXPECT_EQ(*lo, float(adaptive_gamma::lowest)) << "the noise should reach the lower bound";
  EXPECT_EQ(*hi, float(adaptive_gamma::highest)) << "the noise should reach the upper bound";
  // And the solver accepts the result: tau = 3 gamma + 1/2 is above 1/2 in every cell.
  EXPECT_NO_THROW(solver.setGammaPerCell(gamma));
}

// A sphere of radius 8 with noise of +-0.3 voxel in every cell: its kappa
// spans the clamp range, as a noisy scan's does.
Volume noisySphere(Extent3 extent)
{
  Volume field = testing::sphereDistance(extent, 12.5, 11.0, 13.0, 8.0);
  const Volume noise = testing::randomField(extent, -0.3f, 0.3f, 5);
  for (size_t i = 0; i < field.size(); ++i) field[i] += noise[i];
  return field;
}

// The rule as a loop around the solver (how denoise --anisotropic ran it,
// downloading X and uploading gamma at every step) and inside the solver
// (LatticeSolver::setPaperRule, which the shaders run on the device): the
// same arithmetic, so the same field. The rule divides by gamma, down to
// 0.01, at every step, so any difference in rounding would grow a
// hundredfold a step: a loose tolerance would prove little.
template <class Solver, class Field>
Field hostLoop(Solver& solver, const Field& start, const Field& uniformGamma, int steps, double halfWidth)
{
  solver.setGammaPerCell(uniformGamma);
  if constexpr (std::is_same_v<Field, Volume>)
    solver.initialize(start);
  else
    solver.initialize(start, halfWidth);
  Field before = solver.field(), gamma = uniformGamma;
  for (int s = 0; s < steps; ++s) {
    solver.step(1);
    Field after = solver.field();
    gamma = adaptive_gamma::paperRule(before, after, gamma, gamma0);
    solver.setGammaPerCell(gamma);
    before = std::move(after);
  }
  return before;
}

template <class Solver, class Field>
Field insideTheSolver(Solver& solver, const Field& start, int steps, double halfWidth)
{
  solver.setPaperRule(gamma0);
  if constexpr (std::is_same_v<Field, Volume>)
    solver.initialize(start);
  else
    solver.initialize(start, halfWidth);
  solver.step(steps);
  return solver.field();
}

double maxDifference(const std::vector<float>& a, const std::vector<float>& b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, double(std::abs(a[i] - b[i])));
  return worst;
}

TEST(PaperRule, TheGridSolverAppliesItAsTheHostLoopDid)
{
  const Extent3 extent{26, 23, 27};
  const Volume start = noisySphere(extent);
  ReferenceSolver loop(extent), inside(extent);
  const Volume a = hostLoop(loop, start, Volume(extent, float(gamma0)), 7, 0.0);
  const Volume b = insideTheSolver(inside, start, 7, 0.0);
  EXPECT_LT(maxDifference(a.values(), b.values()), 1e-6);
  // The rule made a difference: the isotropic steps end elsewhere.
  ReferenceSolver isotropic(extent);
  isotropic.setUniformGamma(gamma0);
  isotropic.initialize(start);
  isotropic.step(7);
  EXPECT_GT(maxDifference(isotropic.field().values(), b.values()), 0.05);
}

TEST(PaperRule, TheBandSolverAppliesItAsTheHostLoopDid)
{
  const Extent3 extent{26, 23, 27};
  const Volume field = noisySphere(extent);
  auto bricks = testing::bricksNear(field, 7.0);
  const BandField start = testing::bandOf(field, bricks);
  BandField uniform(bricks, start.farValue());
  std::fill(uniform.values().begin(), uniform.values().end(), float(gamma0));
  BandReferenceSolver loop(bricks), inside(bricks);
  const BandField a = hostLoop(loop, start, uniform, 7, 6.0);
  const BandField b = insideTheSolver(inside, start, 7, 6.0);
  EXPECT_LT(maxDifference(a.values(), b.values()), 1e-6);
  BandReferenceSolver isotropic(bricks);
  isotropic.setUniformGamma(gamma0);
  isotropic.initialize(start, 6.0);
  isotropic.step(7);
  EXPECT_GT(maxDifference(isotropic.field().values(), b.values()), 0.05);
}

// The rule's state (each cell's X before and gamma) is seeded by
// initialize(): stepping with a rule set after it is a programming error.
TEST(PaperRule, TakesEffectAtInitialize)
{
  const Extent3 extent{12, 11, 13};
  const Volume start = noisySphere(extent);
  ReferenceSolver grid(extent);
  grid.setUniformGamma(gamma0);
  grid.initialize(start);
  grid.setPaperRule(gamma0);
  EXPECT_THROW(grid.step(1), std::logic_error);
  grid.initialize(start);
  EXPECT_NO_THROW(grid.step(2));
  auto bricks = testing::bricksNear(start, 6.0);
  BandReferenceSolver band(bricks);
  band.initialize(testing::bandOf(start, bricks), 5.0);
  band.setPaperRule(gamma0);
  EXPECT_THROW(band.step(2), std::logic_error);
  band.initialize(testing::bandOf(start, bricks), 5.0);
  EXPECT_NO_THROW(band.step(2));
}

TEST(PaperRule, RefusesASource)
{
  const Extent3 extent{8, 8, 8};
  ReferenceSolver solver(extent);
  solver.setPaperRule(gamma0);
  solver.setSource(LinearSource{Volume(extent, 0.1f), 0.1f});
  EXPECT_THROW(solver.initialize(Volume(extent, 1.0f)), std::invalid_argument);
}

// X of an axis-aligned box, positive inside, exact: the distance to the
// nearest face inside, the distance to the box outside.
Volume boxDistance(Extent3 extent, glm::dvec3 lo, glm::dvec3 hi)
{
  Volume v(extent);
  for (int z = 0; z < extent.nz; ++z)
    for (int y = 0; y < extent.ny; ++y)
      for (int x = 0; x < extent.nx; ++x) {
        const glm::dvec3 p(x, y, z), c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
        const glm::dvec3 q = glm::abs(p - c) - h;
        const double outside = glm::length(glm::max(q, 0.0)), inside = std::min(std::max({q.x, q.y, q.z}), 0.0);
        v.at(x, y, z) = float(-(outside + inside));
      }
  return v;
}

TEST(FeaturePreservingRule, GammaIsSmallerAtABoxEdgeThanOnAFace)
{
  // The same probe as denoise --preserve-features: smoothed until
  // 2 gamma t = 4 voxels^2 (10 steps at 0.2), edges where the mean curvature
  // is 0.2 per voxel.
  const Extent3 extent{40, 40, 40};
  const Volume field = boxDistance(extent, glm::dvec3(8.3), glm::dvec3(31.3));
  ReferenceSolver solver(extent);
  solver.setUniformGamma(gamma0);
  solver.initialize(field);
  solver.step(10);
  const Volume gamma = adaptive_gamma::featurePreservingRule(solver.field(), gamma0, 0.2);

  // At the centre of a face (x = 8.3) and on the middle of the edge where the
  // faces x = 8.3 and y = 8.3 meet, in the cells just inside each.
  const float face = gamma.at(9, 20, 20), edge = gamma.at(9, 9, 20);
  EXPECT_NEAR(face, gamma0, 0.02 * gamma0) << "a flat face gets (nearly) the full gamma";
  EXPECT_LT(edge, 0.5 * gamma0) << "the edge diffuses at most half as fast";
  for (float g : gamma.values()) {
    ASSERT_GE(g, float(adaptive_gamma::lowest));
    ASSERT_LE(g, float(gamma0));
  }
}

}  // namespace
}  // namespace lbmshape
