#include "pipeline/smoothing_stop.hpp"

#include <cmath>

namespace lbmshape::smoothing_stop {

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
  double sum = 0.0;
  size_t k = 0;
  for (size_t i = 0; i < field.size(); ++i)
    if (onSurface_[i]) sum += std::abs(double(field[i]) - double(surface_[k++]));
  const double speed = surface_.empty() ? 0.0 : sum / double(surface_.size());
  remember(field);
  return speed;
}

}  // namespace lbmshape::smoothing_stop
