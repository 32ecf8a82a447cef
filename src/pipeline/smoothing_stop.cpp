#include "lbmshape/pipeline/smoothing_stop.hpp"

#include <cmath>

#include "lbmshape/lbm/surface_change.hpp"
#include "lbmshape/pipeline/feature_probe.hpp"
#include "lbmshape/pipeline/smoothing_radius.hpp"

namespace lbmshape::smoothing_stop {

int fewestStepsForNoise(double amplitudeVoxels, double gamma)
{
  const double spread = noiseMargin * amplitudeVoxels;
  if (spreadVariance(gamma, mostSteps) < spread * spread) return mostSteps;
  return stepsForRadius(spread, gamma);
}

void SurfaceSpeed::remember(const std::vector<float>& field)
{
  // Cells beyond the grid hold the far value, never below 1 voxel: left out.
  onSurface_.assign(field.size(), false);
  surface_.clear();
  for (size_t i = 0; i < field.size(); ++i)
    if (std::abs(field[i]) < 1.0f) {
      onSurface_[i] = true;
      surface_.push_back(field[i]);
    }
}

double SurfaceSpeed::advance(const std::vector<float>& field)
{
  SurfaceChangeSums sums;
  size_t k = 0;
  for (size_t i = 0; i < field.size(); ++i)
    if (onSurface_[i]) sums.add(surface_[k++], field[i]);
  remember(field);
  return sums.speed();
}

}  // namespace lbmshape::smoothing_stop
