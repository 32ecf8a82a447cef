#pragma once

#include "lbmshape/bench/lattice_bench.hpp"
#include "common_options.hpp"
#include "lbmshape/core/extent.hpp"

namespace lbmshape::cli {

// `lbmshape bench --band`: the narrow-band lattice on the band a denoise
// would make around a sphere in a grid of `extent`, streaming `halfWidth`
// voxels each side, on the device and on the CPU reference.
void runBandBench(const CommonOptions& common, const Extent3& extent, const BenchSettings& settings, double halfWidth);

}  // namespace lbmshape::cli
