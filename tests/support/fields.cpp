#include "support/fields.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace lbmshape::testing {

Volume randomField(Extent3 extent, float lo, float hi, uint32_t seed)
{
  Volume v(extent);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> dist(lo, hi);
  for (size_t i = 0; i < v.size(); ++i) v[i] = dist(rng);
  return v;
}

namespace {
template <class F>
Volume sample(Extent3 e, F f)
{
  Volume v(e);
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y)
      for (int x = 0; x < e.nx; ++x) v.at(x, y, z) = float(f(x, y, z));
  return v;
}
}  // namespace

Volume gaussianPulse(Extent3 e, double cx, double cy, double cz, double sigma)
{
  return sample(e, [&](int x, int y, int z) {
    double r2 = (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz);
    return std::exp(-r2 / (2 * sigma * sigma));
  });
}

Volume sphereDistance(Extent3 e, double cx, double cy, double cz, double radius)
{
  return sample(e, [&](int x, int y, int z) {
    return radius - std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz));
  });
}

double sum(const Volume& v)
{
  double s = 0;
  for (size_t i = 0; i < v.size(); ++i) s += v[i];
  return s;
}

double maxDifferenceForItsScale(const Volume& a, const Volume& b)
{
  double worst = 0, scale = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(double(a[i]) - b[i]));
    scale = std::max(scale, std::abs(double(b[i])));
  }
  return scale > 0 ? worst / scale : worst;
}

double maxRelativeDifference(const Volume& a, const Volume& b, double floor)
{
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, std::abs(double(a[i]) - b[i]) / std::max(std::abs(double(b[i])), floor));
  return worst;
}

}  // namespace lbmshape::testing
