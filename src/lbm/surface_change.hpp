// How far the surface moved in one step: the mean |X after - X before| over
// the cells where |X before| < 1 voxel (the cells the surface passes
// through). --steps auto reads the noise off it (pipeline/smoothing_stop.hpp);
// band_speed.comp sums the same on the device.
#pragma once

#include <vector>

namespace lbmshape {

// 0 when no cell of `before` is within a voxel of the surface.
double meanSurfaceChange(const std::vector<float>& after, const std::vector<float>& before);

}  // namespace lbmshape
