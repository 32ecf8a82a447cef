#include "lbm/adaptive_gamma.hpp"

#include <algorithm>
#include <cmath>

#include "lbm/solver_state.hpp"

namespace lbmshape::adaptive_gamma {

Volume paperRule(const Volume& before, const Volume& after, const Volume& gammaUsed, double gamma0)
{
  solver_state::checkSameExtent(before.extent(), after.extent(), "field");
  solver_state::checkSameExtent(before.extent(), gammaUsed.extent(), "gamma");
  Volume gamma(before.extent());
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < gamma.size(); ++i) {
    const double kappa = (double(after[i]) - before[i]) / gammaUsed[i];
    gamma[i] = float(std::clamp(gamma0 + kappa, lowest, highest));
  }
  return gamma;
}

Volume laplacian(const Volume& field)
{
  const Extent3& e = field.extent();
  Volume out(e);
  auto at = [&](int x, int y, int z) {
    // A mirrored neighbour beyond the grid: zero flux through the faces.
    x = std::clamp(x, 0, e.nx - 1), y = std::clamp(y, 0, e.ny - 1), z = std::clamp(z, 0, e.nz - 1);
    return double(field.at(x, y, z));
  };
#pragma omp parallel for collapse(2) schedule(static)
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y)
      for (int x = 0; x < e.nx; ++x)
        out.at(x, y, z) = float(at(x - 1, y, z) + at(x + 1, y, z) + at(x, y - 1, z) + at(x, y + 1, z) +
                                at(x, y, z - 1) + at(x, y, z + 1) - 6.0 * at(x, y, z));
  return out;
}

Volume featurePreservingRule(const Volume& smoothed, double gamma0, double kappaEdge)
{
  Volume kappa = laplacian(smoothed);
  Volume gamma(smoothed.extent());
  const double lo = std::min(lowest, gamma0);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < gamma.size(); ++i) {
    const double r = kappa[i] / kappaEdge;
    gamma[i] = float(std::clamp(gamma0 / (1.0 + r * r), lo, gamma0));
  }
  return gamma;
}

}  // namespace lbmshape::adaptive_gamma
