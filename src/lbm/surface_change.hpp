// How far the surface moved in one step, less what a level-set shift
// undoes: the standard deviation of X after - X before over the cells
// where |X before| < 1 voxel (the cells the surface passes through).
// A uniform move of the whole surface (mean-curvature flow's shrinking of
// a tube, a sphere) changes the mean alone, and keeping the volume shifts
// it back; the noise and the shape's uneven motion are what stays. So a
// thin tube that shrinks as the noise goes reads the noise, not its own
// shrinking (docs/denoising.md, "How many steps"). --steps auto reads the
// noise off it (pipeline/smoothing_stop.hpp); band_speed.comp sums the same
// on the device.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace lbmshape {

// The sums the speed is made of: of the change, of its square, and the
// cells; the device adds them a row at a time, the host in double.
struct SurfaceChangeSums {
  double change = 0.0, squares = 0.0, cells = 0.0;

  void add(float before, float after)
  {
    if (std::abs(before) >= 1.0f) return;
    const double d = double(after) - double(before);
    change += d, squares += d * d, cells += 1.0;
  }
  SurfaceChangeSums& operator+=(const SurfaceChangeSums& o)
  {
    change += o.change, squares += o.squares, cells += o.cells;
    return *this;
  }
  // Voxels a step; 0 when no cell was within a voxel of the surface.
  double speed() const
  {
    if (cells == 0.0) return 0.0;
    const double mean = change / cells;
    return std::sqrt(std::max(0.0, squares / cells - mean * mean));
  }
};

// Over cells 0..count-1, read through after(i) and before(i).
template <class After, class Before>
double surfaceSpeedOf(size_t count, After after, Before before)
{
  double change = 0.0, squares = 0.0, cells = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : change, squares, cells)
  for (size_t i = 0; i < count; ++i) {
    SurfaceChangeSums one;
    one.add(before(i), after(i));
    change += one.change, squares += one.squares, cells += one.cells;
  }
  return SurfaceChangeSums{change, squares, cells}.speed();
}

// The same over two fields of equal size.
double surfaceSpeed(const std::vector<float>& after, const std::vector<float>& before);

}  // namespace lbmshape
