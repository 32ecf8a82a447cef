#include "lbmshape/lbm/relaxation.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/lbm/d3q19.hpp"

namespace lbmshape::relaxation {

double tauFromGamma(double gamma) { return gamma / d3q19::soundSpeedSquared + 0.5; }
double gammaFromTau(double tau) { return d3q19::soundSpeedSquared * (tau - 0.5); }

void checkGamma(double gamma, std::string_view what)
{
  if (acceptableGamma(gamma)) return;
  // What is wrong, for the message.
  const auto name = [what] { return what.empty() ? nameOf(Parameter::Gamma) : std::string(what); };
  if (!std::isfinite(gamma) || gamma <= 0.0) {
    std::ostringstream message;
    message << name() << " must be a positive number of voxels^2 per step (got " << numberText(gamma)
            << "); it sets tau = 3*gamma + 1/2, and tau <= 1/2 is unstable";
    throw UsageError(message.str());
  }
  if (gamma > parameter_bounds::maxGamma) {
    std::ostringstream message;
    message << name() << " = " << numberText(gamma) << " is above " << parameter_bounds::maxGamma
            << " voxel^2 per step, where the lattice stops following the diffusion equation (tau = 3*gamma + 1/2 > 3.5"
            << " relaxes too slowly); for more smoothing, give more steps";
    throw UsageError(message.str());
  }
  // The reason left: the lattice computes in fp32, and below about 5e-9
  // omega = 1/tau rounds to exactly 2, which is tau = 1/2 again.
  std::ostringstream message;
  message << name() << " = " << numberText(gamma)
          << " is too small: tau = 3*gamma + 1/2 rounds to 1/2 in single precision,"
          << " where the scheme is unstable; use at least 1e-8";
  throw UsageError(message.str());
}

double startUpError(double gamma, long steps)
{
  const double tau = tauFromGamma(gamma);
  const double decayed = std::pow(1.0 - 1.0 / tau, double(steps));
  return (d3q19::soundSpeedSquared - 2.0 * gamma) * tau * (1.0 - decayed) / (2.0 * gamma * double(steps));
}

void warnIfInaccurate(double gamma, long steps)
{
  if (steps < 1) return;
  const double error = startUpError(gamma, steps);
  if (std::abs(error) <= accurateStartUpError) return;
  std::ostringstream message;
  const std::string what = nameOf(Parameter::Gamma);
  message << what << " = " << gamma << " over " << steps << (steps == 1 ? " step" : " steps") << " smooths "
          << std::fixed << std::setprecision(1) << std::abs(error) * 100.0 << (error < 0 ? " % less" : " % more")
          << " than the diffusion equation (2*gamma*steps) because every run starts in equilibrium; "
          << (error < 0 ? "more steps at a smaller " + what : "more steps, or a " + what + " nearer 1/6,")
          << " stay within " << int(accurateStartUpError * 100) << " % (docs/lattice-theory.md, \"The first steps\")";
  log::warning(message.str());
}

}  // namespace lbmshape::relaxation
