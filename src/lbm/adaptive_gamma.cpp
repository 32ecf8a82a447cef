#include "lbmshape/lbm/adaptive_gamma.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lbmshape/lbm/relaxation.hpp"
#include "lbmshape/lbm/solver_state.hpp"

namespace lbmshape::adaptive_gamma {
namespace {

// The rules cell by cell, on the values of either kind of field.
void paperRuleValues(const std::vector<float>& before, const std::vector<float>& after,
                     const std::vector<float>& gammaUsed, double gamma0, std::vector<float>& gamma)
{
  const float g0 = float(gamma0), lo = float(lowest), hi = float(highest);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < gamma.size(); ++i) gamma[i] = std::clamp(g0 + (after[i] - before[i]) / gammaUsed[i], lo, hi);
}

void featurePreservingValues(const std::vector<float>& kappa, double gamma0, double kappaEdge,
                             std::vector<float>& gamma)
{
  checkFeatureRule(gamma0, kappaEdge);
  const double lo = std::min(lowest, gamma0);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < gamma.size(); ++i) {
    const double r = kappa[i] / kappaEdge;
    gamma[i] = float(std::clamp(gamma0 / (1.0 + r * r), lo, gamma0));
  }
}

}  // namespace

void checkFeatureRule(double gamma0, double kappaEdge)
{
  relaxation::checkGamma(gamma0);
  if (!(kappaEdge > 0.0)) throw std::invalid_argument("the feature rule's edge curvature must be positive");
}

Volume paperRule(const Volume& before, const Volume& after, const Volume& gammaUsed, double gamma0)
{
  solver_state::checkSameExtent(before.extent(), after.extent(), "field");
  solver_state::checkSameExtent(before.extent(), gammaUsed.extent(), "gamma");
  Volume gamma(before.extent());
  paperRuleValues(before.values(), after.values(), gammaUsed.values(), gamma0, gamma.values());
  return gamma;
}

BandField paperRule(const BandField& before, const BandField& after, const BandField& gammaUsed, double gamma0)
{
  BandField gamma(before.sharedBricks(), 0.0f);
  paperRuleValues(before.values(), after.values(), gammaUsed.values(), gamma0, gamma.values());
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
  Volume gamma(smoothed.extent());
  featurePreservingValues(laplacian(smoothed).values(), gamma0, kappaEdge, gamma.values());
  return gamma;
}

BandField laplacian(const BandField& field)
{
  const BrickSet& bricks = field.bricks();
  const Extent3& e = bricks.cells();
  BandField out(field.sharedBricks(), 0.0f);
  auto at = [&](int x, int y, int z) {
    x = std::clamp(x, 0, e.nx - 1), y = std::clamp(y, 0, e.ny - 1), z = std::clamp(z, 0, e.nz - 1);
    return double(field.at(x, y, z));
  };
#pragma omp parallel for schedule(static)
  for (size_t s = 0; s < bricks.activeCount(); ++s)
    for (int local = 0; local < brickCells; ++local) {
      const glm::ivec3 c = bricks.cell(int32_t(s), local);
      if (!e.contains(c.x, c.y, c.z)) continue;
      out.values()[s * brickCells + size_t(local)] =
          float(at(c.x - 1, c.y, c.z) + at(c.x + 1, c.y, c.z) + at(c.x, c.y - 1, c.z) + at(c.x, c.y + 1, c.z) +
                at(c.x, c.y, c.z - 1) + at(c.x, c.y, c.z + 1) - 6.0 * at(c.x, c.y, c.z));
    }
  return out;
}

BandField featurePreservingRule(const BandField& smoothed, double gamma0, double kappaEdge)
{
  BandField gamma(smoothed.sharedBricks(), 0.0f);
  featurePreservingValues(laplacian(smoothed).values(), gamma0, kappaEdge, gamma.values());
  return gamma;
}

}  // namespace lbmshape::adaptive_gamma
