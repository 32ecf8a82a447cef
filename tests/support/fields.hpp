// Test fields for the lattice: random, Gaussian, sphere distance.
#pragma once

#include <cstdint>

#include "lbmshape/core/volume.hpp"
#include "lbmshape/lbm/adaptive_gamma.hpp"

namespace lbmshape::testing {

Volume randomField(Extent3 extent, float lo, float hi, uint32_t seed);
// exp(-|r - c|^2 / (2 sigma^2)) around the grid's cell (cx, cy, cz)
Volume gaussianPulse(Extent3 extent, double cx, double cy, double cz, double sigma);
// R - |r - c|: the signed distance of a sphere, positive inside
Volume sphereDistance(Extent3 extent, double cx, double cy, double cz, double radius);

double sum(const Volume& v);
// max over cells of |a - b| / max(|b|, floor)
double maxRelativeDifference(const Volume& a, const Volume& b, double floor = 1e-6);
// max over cells of |a - b|, divided by max over cells of |b|: a difference
// measured against the field's scale, which stays meaningful where the
// field itself passes through zero.
double maxDifferenceForItsScale(const Volume& a, const Volume& b);

// How far a conformant Vulkan device may land from the CPU reference after
// tens of steps, as a fraction of the field's largest magnitude: Vulkan lets
// a device fuse multiply-adds and divide to 2.5 ULP, and each such rounding
// is about 6e-8 of the value it rounds.
inline constexpr double deviceTolerance = 1e-5;
// The same under the paper's anisotropic rule: gamma follows a step's change
// of X divided by the gamma before, at least adaptive_gamma::lowest, so one
// rounding of X is magnified up to 1 / lowest = 100 times in the next gamma.
// Step after step that feedback can grow without bound on a noisy field: a
// comparison under the rule must stop before it has (band_solver_test.cpp,
// paperRuleSteps).
inline constexpr double paperRuleDeviceTolerance = deviceTolerance / adaptive_gamma::lowest;

}  // namespace lbmshape::testing
