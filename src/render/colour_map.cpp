#include "lbmshape/render/colour_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace lbmshape::render {
namespace {

// Piecewise linear through evenly spaced stops, t in [0, 1].
template <size_t N>
glm::vec3 throughStops(const std::array<glm::vec3, N>& stops, double t)
{
  if (!std::isfinite(t)) t = 0.0;
  t = std::clamp(t, 0.0, 1.0) * double(N - 1);
  const size_t i = std::min(size_t(t), N - 2);
  return glm::mix(stops[i], stops[i + 1], float(t - double(i)));
}

}  // namespace

glm::vec3 divergingColour(double t)
{
  static const std::array<glm::vec3, 5> coolWarm = {
      glm::vec3(0.230f, 0.299f, 0.754f), glm::vec3(0.552f, 0.690f, 0.996f), glm::vec3(0.865f, 0.865f, 0.865f),
      glm::vec3(0.958f, 0.604f, 0.482f), glm::vec3(0.706f, 0.016f, 0.150f)};
  if (!std::isfinite(t)) t = 0.0;  // no value: grey
  return throughStops(coolWarm, 0.5 * (t + 1.0));
}

glm::vec3 sequentialColour(double t)
{
  static const std::array<glm::vec3, 5> viridis = {glm::vec3(0.267f, 0.005f, 0.329f), glm::vec3(0.229f, 0.322f, 0.546f),
                                                   glm::vec3(0.128f, 0.567f, 0.551f), glm::vec3(0.369f, 0.789f, 0.383f),
                                                   glm::vec3(0.993f, 0.906f, 0.144f)};
  return throughStops(viridis, t);
}

glm::vec3 legendColour(const Legend& legend, double value)
{
  const double span = legend.high - legend.low;
  const double t = span > 0.0 ? (value - legend.low) / span : 0.5;
  return legend.diverging ? divergingColour(2.0 * t - 1.0) : sequentialColour(t);
}

}  // namespace lbmshape::render
