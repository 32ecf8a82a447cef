#include "lbm/surface_change.hpp"

#include <cmath>
#include <stdexcept>

namespace lbmshape {

double meanSurfaceChange(const std::vector<float>& after, const std::vector<float>& before)
{
  if (after.size() != before.size()) throw std::invalid_argument("two fields of different sizes");
  double sum = 0.0;
  long long count = 0;
#pragma omp parallel for schedule(static) reduction(+ : sum, count)
  for (size_t i = 0; i < before.size(); ++i)
    if (std::abs(before[i]) < 1.0f) {
      sum += std::abs(double(after[i]) - double(before[i]));
      ++count;
    }
  return count > 0 ? sum / double(count) : 0.0;
}

}  // namespace lbmshape
