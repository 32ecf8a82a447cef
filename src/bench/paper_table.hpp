// Table 1 of the paper: per-step times of its LBM on a 2008 CPU (Intel Core 2
// 6300) and GPU (GeForce 8800 GTX), for the lattices of its figures.
#pragma once

#include <array>

#include "lbmshape/core/extent.hpp"

namespace lbmshape::paper {

struct TableRow {
  const char* application;
  const char* figure;
  Extent3 size;
  double cpuMs;
  double gpuMs;
  double textureMegabytes;
};

inline constexpr std::array<TableRow, 5> table1 = {{
    {"denoising", "Figure 3", {70, 123, 66}, 672, 3.1, 109.1},
    {"denoising", "Figure 4", {107, 128, 97}, 1559, 6.2, 236.2},
    {"denoising", "Figure 6", {58, 128, 106}, 909, 3.7, 138.5},
    {"morphing", "Figure 8", {128, 128, 128}, 2523, 14.5, 402.6},
    {"morphing", "Figure 9", {80, 80, 80}, 580, 4.5, 98.3},
}};

}  // namespace lbmshape::paper
