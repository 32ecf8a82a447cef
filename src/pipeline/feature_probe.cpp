#include "lbmshape/pipeline/feature_probe.hpp"

#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/lbm/relaxation.hpp"

namespace lbmshape {

double spreadVariance(double gamma, int steps)
{
  return 2.0 * gamma * steps * (1.0 + relaxation::startUpError(gamma, steps));
}

FeatureProbe featureProbe()
{
  // The spread grows with gamma at any number of steps: the fewest steps are
  // those that reach the variance at the largest gamma, and bisection finds
  // the gamma that reaches it exactly.
  FeatureProbe probe;
  probe.steps = 1;
  while (spreadVariance(parameter_bounds::maxGamma, probe.steps) < featureProbeVariance) ++probe.steps;
  double lo = 1e-3, hi = parameter_bounds::maxGamma;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (spreadVariance(mid, probe.steps) < featureProbeVariance ? lo : hi) = mid;
  }
  probe.gamma = hi;
  return probe;
}

}  // namespace lbmshape
