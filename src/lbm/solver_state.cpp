#include "lbmshape/lbm/solver_state.hpp"

#include <cmath>
#include <sstream>

#include "lbmshape/core/error.hpp"
#include "lbmshape/lbm/relaxation.hpp"

namespace lbmshape::solver_state {

Volume omegaFromGammaVolume(const Volume& gamma)
{
  Volume omega(gamma.extent());
  for (size_t i = 0; i < gamma.size(); ++i) {
    relaxation::checkGamma(gamma[i], "per-cell gamma");
    omega[i] = relaxation::singlePrecisionOmega(gamma[i]);
  }
  return omega;
}

void checkPaperRuleWithoutSource(bool paperRule, bool source)
{
  if (paperRule && source) throw std::invalid_argument("the paper's anisotropic rule runs without a source");
}

Volume initialDensity(const Volume& field, const std::optional<LinearSource>& source)
{
  if (!source) return field;
  checkSameExtent(field.extent(), source->base.extent(), "source");
  Volume density(field.extent());
  for (size_t i = 0; i < field.size(); ++i) {
    float s = source->scale * source->base[i] - source->decay * field[i];
    density[i] = field[i] - 0.5f * s;
  }
  return density;
}

void checkSameExtent(const Extent3& expected, const Extent3& got, const char* what)
{
  if (expected != got) {
    std::ostringstream message;
    message << what << " volume is " << got.toString() << " but the lattice is " << expected.toString();
    throw std::invalid_argument(message.str());
  }
}

}  // namespace lbmshape::solver_state
