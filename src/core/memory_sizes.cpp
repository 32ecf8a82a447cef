#include "lbmshape/core/memory_sizes.hpp"

#include "lbmshape/core/parameter_names.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lbmshape {

std::string mebibytes(uint64_t bytes)
{
  std::ostringstream s;
  s.precision(1);
  s << std::fixed << double(bytes) / (1024.0 * 1024.0) << " MiB";
  return s.str();
}

int longestSideThatFits(const Extent3& extent, double needed, double allowed, double power)
{
  const int longest = std::max({extent.nx, extent.ny, extent.nz});
  const double fits = std::floor(0.95 * longest * std::pow(allowed / needed, 1.0 / power));
  return int(std::clamp(fits, 0.0, double(INT32_MAX)));
}

std::string gridThatWouldFit(const Extent3& extent, double needed, double allowed, double power, int cap)
{
  const int fits = std::min(cap, longestSideThatFits(extent, needed, allowed, power));
  if (fits < coarsestGrid)
    return "no grid would fit (not even " + nameOf(Parameter::Resolution) + " " + std::to_string(coarsestGrid) +
           "); raise the memory limit";
  return "a grid of about " + std::to_string(fits) + " cells along its longest side (" + nameOf(Parameter::Resolution) +
         " " + std::to_string(fits) + ") would fit";
}

}  // namespace lbmshape
