// Test fields for the lattice: random, Gaussian, sphere distance.
#pragma once

#include <cstdint>

#include "core/volume.hpp"

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

}  // namespace lbmshape::testing
