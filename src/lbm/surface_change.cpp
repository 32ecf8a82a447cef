#include "lbmshape/lbm/surface_change.hpp"

#include <stdexcept>

namespace lbmshape {

double surfaceSpeed(const std::vector<float>& after, const std::vector<float>& before)
{
  if (after.size() != before.size()) throw std::invalid_argument("two fields of different sizes");
  return surfaceSpeedOf(
      before.size(), [&](size_t i) { return after[i]; }, [&](size_t i) { return before[i]; });
}

}  // namespace lbmshape
