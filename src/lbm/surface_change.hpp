// How far the surface moved in one step: the mean |X after - X before| over
// the cells where |X before| < 1 voxel (the cells the surface passes
// through). --steps auto reads the noise off it (pipeline/smoothing_stop.hpp);
// band_speed.comp sums the same on the device.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace lbmshape {

// Over cells 0..count-1, read through after(i) and before(i); 0 when no cell
// of `before` is within a voxel of the surface.
template <class After, class Before>
double meanSurfaceChangeOf(size_t count, After after, Before before)
{
  double sum = 0.0;
  long long near = 0;
#pragma omp parallel for schedule(static) reduction(+ : sum, near)
  for (size_t i = 0; i < count; ++i) {
    const float b = before(i);
    if (std::abs(b) < 1.0f) {
      sum += std::abs(double(after(i)) - double(b));
      ++near;
    }
  }
  return near > 0 ? sum / double(near) : 0.0;
}

// The same over two fields of equal size.
double meanSurfaceChange(const std::vector<float>& after, const std::vector<float>& before);

}  // namespace lbmshape
