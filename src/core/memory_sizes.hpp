// Words for memory in the messages that refuse a job too large for a device
// or the host: one format for the sizes, one rule for the grid that would fit.
#pragma once

#include <climits>
#include <cstdint>
#include <string>

#include "lbmshape/core/extent.hpp"

namespace lbmshape {

// "12.3 MiB".
std::string mebibytes(uint64_t bytes);

// "a grid of about N cells along its longest side (--res N) would fit" (the
// resolution named as core/parameter_names.hpp says), for
// a job on `extent` that needs `needed` where `allowed` is available, its
// size growing as the grid's side to the power `power` (3 for a grid, 2 for
// a band, which follows the surface's area); with a 5 % margin. A job
// checked against two limits (the device's and, for a device that is the
// CPU, the host's) gives each check the other's largest side as `cap`, so
// that the grid named fits both: named by one alone, it was refused by the
// other.
// The coarsest grid any mesh gets (12 cells with the default margin:
// grid_frame.hpp): a refusal names no --res below it, which would be
// advice that fails in turn.
inline constexpr int coarsestGrid = 12;

std::string gridThatWouldFit(const Extent3& extent, double needed, double allowed, double power, int cap = INT32_MAX);

// N of gridThatWouldFit's message.
int longestSideThatFits(const Extent3& extent, double needed, double allowed, double power);

}  // namespace lbmshape
