#include "lbm/relaxation.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "lbm/d3q19.hpp"

namespace lbmshape::relaxation {

double tauFromGamma(double gamma) { return gamma / d3q19::soundSpeedSquared + 0.5; }
double gammaFromTau(double tau) { return d3q19::soundSpeedSquared * (tau - 0.5); }

void checkGamma(double gamma, const char* what)
{
  if (!std::isfinite(gamma) || gamma <= 0.0) {
    std::ostringstream message;
    message << what << " must be a positive number of voxels^2 per step (got " << gamma
            << "); it sets tau = 3*gamma + 1/2, and tau <= 1/2 is unstable";
    throw UsageError(message.str());
  }
}

}  // namespace lbmshape::relaxation
